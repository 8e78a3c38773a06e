#pragma once
#include "reference/bullet_engine.h"

namespace reference {

// One file each; the model has passed checkSupported() for the engine, and is not the circle.
std::unique_ptr<BulletStepper> makeDeformableStepper(const mysim::Model& model,
                                                     const BulletSettings& settings, bool implicit);
std::unique_ptr<BulletStepper> makeClassicStepper(const mysim::Model& model,
                                                  const BulletSettings& settings);

}  // namespace reference
