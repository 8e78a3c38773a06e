#include <cmath>

#include "reference/bullet_engine.h"

namespace reference {

const std::vector<std::string>& bulletEngineNames() {
  static const std::vector<std::string> names = {"bullet-deformable", "bullet-implicit",
                                                 "bullet-classic"};
  return names;
}

const char* bulletEngineName(BulletEngine engine) {
  switch (engine) {
    case BulletEngine::Deformable:
      return "bullet-deformable";
    case BulletEngine::Implicit:
      return "bullet-implicit";
    case BulletEngine::Classic:
      return "bullet-classic";
  }
  return "?";
}

std::expected<BulletEngine, std::string> bulletEngineNamed(const std::string& name) {
  for (BulletEngine e : {BulletEngine::Deformable, BulletEngine::Implicit, BulletEngine::Classic}) {
    if (name == bulletEngineName(e)) return e;
  }
  return std::unexpected("unknown Bullet engine '" + name + "'");
}

double classicLinkStiffness(double k, double h, double inverse_mass_sum, int iterations) {
  const double a = k * h * h * inverse_mass_sum;
  const double alpha = a / (1.0 + a);
  return 1.0 - std::pow(1.0 - alpha, 1.0 / iterations);
}

}  // namespace reference
