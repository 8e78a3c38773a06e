#pragma once
#include "reference/bullet_engine.h"

namespace reference {

// One file each; the scene has passed checkSupported() for the engine.
std::unique_ptr<BulletStepper> makeDeformableStepper(const mysim::Scene& scene,
                                                     const mysim::Model& model, bool implicit);
std::unique_ptr<BulletStepper> makeClassicStepper(const mysim::Scene& scene,
                                                  const mysim::Model& model);

}  // namespace reference
