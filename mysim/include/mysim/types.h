#pragma once
// Shared numeric types. Units are SI throughout (m, kg, s, N); see docs/scenes.md.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <string>

namespace mysim {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Vector = Eigen::VectorXd;

// User text (a key, a name, a path) as messages quote it: at most `max` characters, so a hostile
// or mistaken input cannot flood a message.
inline std::string clip(const std::string& text, std::size_t max = 80) {
  return text.size() <= max ? text : text.substr(0, max - 3) + "...";
}

// A particle's 3-vector inside a flat 3N array, without copying.
inline auto at3(Vector& v, int particle) { return v.segment<3>(3 * particle); }
inline auto at3(const Vector& v, int particle) { return v.segment<3>(3 * particle); }

}  // namespace mysim
