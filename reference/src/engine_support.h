#pragma once
#include <expected>
#include <string>

#include "reference/bullet_engine.h"

namespace reference {

// Refuses, naming the engine and the scene field, what a Bullet engine cannot represent, so no
// force term is ever dropped silently.
[[nodiscard]] std::expected<void, std::string> checkSupported(const mysim::Scene& scene,
                                                              const mysim::Model& model,
                                                              BulletEngine engine);

// The scene field a spring's parameter came from ("system.shear.damping", "system.springs[4]...").
std::string springField(const mysim::Scene& scene, const mysim::Spring& spring, int index,
                        const std::string& parameter);

// Mass shared by every free particle, or 0 if they differ.
double uniformFreeMass(const mysim::Model& model);

}  // namespace reference
