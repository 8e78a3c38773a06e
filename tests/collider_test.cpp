// Static colliders: each shape's signed distance and contact point against closed forms, the
// contact normal against the gradient of the signed distance, and the scene file's list.
//
//   plane y = 0, normal +y        box centred at c, half extents e
//        . x (above: no contact)       +-------+
//   -----+------ margin                |   . x | inside: out through the nearest face
//   ~~~~~~~~~~~~ solid                 +-------+
// ctest-label: unit
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "mysim/collider.h"
#include "mysim/contact.h"
#include "mysim/scene_file.h"

namespace mysim {
namespace {

TEST(PlaneCollider, PutsATouchingParticleAtTheMarginAndKeepsItsTangentialVelocity) {
  const Plane ground{Vec3(0, 1, 0), Vec3::UnitY(), 0.01};
  EXPECT_DOUBLE_EQ(signedDistance(ground, Vec3(3, 1.5, -2)), 0.5);
  EXPECT_FALSE(contactPoint(ground, Vec3(0, 1.02, 0)));  // beyond the margin
  Vector x = (Vector(3) << 0.3, 0.9, 0.2).finished(), v = (Vector(3) << 1, -2, 3).finished();
  EXPECT_EQ(resolveContacts({ground}, {0}, Vector(x), x, v), 1);
  EXPECT_EQ(Vec3(x), Vec3(0.3, 1.01, 0.2));
  EXPECT_EQ(Vec3(v), Vec3(1, 0, 3));
}

TEST(BoxCollider, SignedDistanceIsExactOnEveryRegion) {
  const Box box{Vec3(1, 2, 3), Vec3(0.5, 1, 2), 0.0};
  EXPECT_DOUBLE_EQ(signedDistance(box, Vec3(2, 2, 3)), 0.5);               // beside a face
  EXPECT_DOUBLE_EQ(signedDistance(box, Vec3(1.5 + 3, 3 + 4, 3)), 5.0);     // off an edge (3-4-5)
  EXPECT_NEAR(signedDistance(box, Vec3(1.4, 2, 3)), -0.1, 1e-15);         // inside, near +x face
  EXPECT_DOUBLE_EQ(signedDistance(box, Vec3(1, 2, 3)), -0.5);              // the centre
  EXPECT_NEAR(signedDistance(box, Vec3(1.5 + 1, 3 + 1, 5 + 1)), std::sqrt(3.0), 1e-15);
}

TEST(BoxCollider, ContactLeavesThroughTheNearestFaceOrAlongTheLineFromTheNearestPoint) {
  const Box box{Vec3::Zero(), Vec3(1, 1, 1), 0.1};
  const auto inside = contactPoint(box, Vec3(0.2, 0.9, -0.3));  // nearest face: +y
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->point, Vec3(0.2, 1.1, -0.3));
  EXPECT_EQ(inside->normal, Vec3::UnitY());
  const auto corner = contactPoint(box, Vec3(1.03, 1.04, 0.5));  // 0.05 off an edge
  ASSERT_TRUE(corner);
  EXPECT_TRUE(corner->point.isApprox(Vec3(1 + 0.06, 1 + 0.08, 0.5), 1e-14));
  EXPECT_FALSE(contactPoint(box, Vec3(1.2, 0, 0)));
}

// A thin wall (2 cm, cloth_over_thin_wall's): a step that carries a node from above the top
// deeper than the half thickness leaves it nearer a side than the top; it goes back out the top,
// the way it came in. One that came in through a side goes back out that side; one that was
// inside already leaves through the nearest face.
TEST(BoxCollider, ANodeCarriedDeepIntoAThinWallLeavesTheWayItCameIn) {
  const Box wall{Vec3(0, 0.5, 0), Vec3(0.01, 0.1, 0.6), 1e-3};
  const Vec3 deep(0.004, 0.585, 0.2);  // 1.5 cm below the top, 0.6 cm from the +x side
  const auto from_above = contactPoint(wall, deep, [](const Vec3&) { return false; },
                                       Vec3(0.003, 0.61, 0.2));
  ASSERT_TRUE(from_above);
  EXPECT_EQ(from_above->normal, Vec3::UnitY());
  EXPECT_NEAR(from_above->point.y(), 0.601, 1e-15);
  EXPECT_EQ(from_above->point.x(), deep.x());
  const auto from_side = contactPoint(wall, deep, [](const Vec3&) { return false; },
                                      Vec3(-0.02, 0.59, 0.2));
  ASSERT_TRUE(from_side);
  EXPECT_EQ(from_side->normal, -Vec3::UnitX());  // entered the -x side, crossed nearly through
  const auto already_inside = contactPoint(wall, deep);
  ASSERT_TRUE(already_inside);
  EXPECT_EQ(already_inside->normal, Vec3::UnitX());  // the nearest face
}

// A box standing on the ground (its bottom face on the plane): a node just inside near the
// bottom leaves through the nearest face that does not lead into the ground, here its side,
// and ends outside both. The point is one a cloth run met: its clamped nearest point differs from
// it by round-off, which must not read as "outside".
TEST(Colliders, ABoxOnTheGroundNeverPushesANodeOutThroughItsBottom) {
  const std::vector<Collider> ground_and_box = {Box{Vec3(0, 0.15, 0), Vec3(0.2, 0.15, 0.2), 1e-3},
                                                Plane{Vec3::Zero(), Vec3::UnitY(), 1e-3}};
  Vector x = (Vector(3) << -0.04748955, 0.00218487, 0.1918533).finished();
  Vector v = (Vector(3) << -0.05, 0.0, -0.3).finished();
  resolveContacts(ground_and_box, {0}, Vector(x), x, v);
  EXPECT_NEAR(x[2], 0.201, 1e-15);  // out through the +z side to the margin
  EXPECT_DOUBLE_EQ(x[1], 0.00218487);
  EXPECT_GE(signedDistance(ground_and_box[0], Vec3(x)), 1e-3 - 1e-15);
  EXPECT_GT(signedDistance(ground_and_box[1], Vec3(x)), 0.0);
  EXPECT_EQ(v[2], 0.0);  // its inward (-z) velocity removed
}

// Outside each shape (but within its margin), the contact normal is the gradient of the signed
// distance, and the contact point lies on the grown surface: distance = margin.
TEST(Colliders, ContactNormalIsTheSignedDistanceGradientAndThePointLiesAtTheMargin) {
  const std::vector<Collider> shapes = {Sphere{Vec3(0.1, -0.2, 0.3), 0.7, 0.2},
                                        Plane{Vec3(0, 0.5, 0), Vec3(1, 2, 2).normalized(), 0.2},
                                        Box{Vec3(-0.1, 0.2, 0), Vec3(0.3, 0.5, 0.4), 0.2}};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int checked = 0;
  for (const Collider& c : shapes) {
    for (int k = 0; k < 2000; ++k) {
      const Vec3 x(u(rng), u(rng), u(rng));
      const double d = signedDistance(c, x);
      if (d <= 1e-3 || d >= colliderMargin(c)) continue;  // only the band outside, in the margin
      const auto s = contactPoint(c, x);
      ASSERT_TRUE(s) << colliderType(c);
      Vec3 gradient;
      const double h = 1e-6;
      for (int a = 0; a < 3; ++a) {
        const Vec3 e = h * Vec3::Unit(a);
        gradient[a] = (signedDistance(c, x + e) - signedDistance(c, x - e)) / (2 * h);
      }
      EXPECT_LT((s->normal - gradient).norm(), 1e-6) << colliderType(c);
      EXPECT_NEAR(signedDistance(c, s->point), colliderMargin(c), 1e-12) << colliderType(c);
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);  // the band was sampled for every shape
}

TEST(Colliders, SceneFileReadsEveryTypeAfterTheSeedsSphere) {
  auto scene = parseScene(R"({
    "system": {"type": "particles", "particles": [{"position": [0, 1, 0], "mass": 1}]},
    "sphere": {"center": [0, 0, 0], "radius": 0.5},
    "colliders": [{"type": "plane", "point": [0, -1, 0], "normal": [0, 2, 0]},
                  {"type": "box", "center": [2, 0, 0], "half_extents": [1, 1, 1]}],
    "integrator": {"dt": 0.01, "duration": 0.1}})",
                          "colliders.json");
  ASSERT_TRUE(scene) << scene.error();
  ASSERT_EQ(scene->colliders.size(), 3u);
  EXPECT_STREQ(colliderType(scene->colliders[0]), "sphere");
  EXPECT_EQ(std::get<Plane>(scene->colliders[1]).normal, Vec3::UnitY());  // normalised
  EXPECT_DOUBLE_EQ(std::get<Box>(scene->colliders[2]).margin, 1e-3);     // 1e-3 smallest half
}

TEST(Colliders, SceneFileRefusesAnUnknownTypeAndABadBoxNamingTheField) {
  const std::string head = R"({"system": {"type": "particles", "particles": [{"position": [0, 1, 0], "mass": 1}]},
    "integrator": {"dt": 0.01, "duration": 0.1}, "colliders": )";
  auto unknown = parseScene(head + R"([{"type": "cone"}]})", "c.json");
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().find("colliders[0].type"), std::string::npos) << unknown.error();
  EXPECT_NE(unknown.error().find("sphere, plane, box"), std::string::npos) << unknown.error();
  auto flat = parseScene(head + R"([{"type": "box", "center": [0, 0, 0], "half_extents": [1, 0, 1]}]})",
                         "c.json");
  ASSERT_FALSE(flat);
  EXPECT_NE(flat.error().find("colliders[0].half_extents"), std::string::npos) << flat.error();
  auto extra = parseScene(head + R"([{"type": "plane", "point": [0, 0, 0], "radius": 1}]})", "c.json");
  ASSERT_FALSE(extra);
  EXPECT_NE(extra.error().find("colliders[0].radius"), std::string::npos) << extra.error();
}

// Every shape of the variant, default-made: the tests below hold for any shape added to it.
template <std::size_t... I>
std::vector<Collider> everyShape(std::index_sequence<I...>) {
  return {Collider(std::variant_alternative_t<I, Collider>{})...};
}
std::vector<Collider> everyShape() {
  return everyShape(std::make_index_sequence<std::variant_size_v<Collider>>{});
}

TEST(ColliderDrawing, EveryShapesQuadsLieOnItsSurfaceLessTheInsetFacingOut) {
  SurfaceDrawing drawing{Vec3(-0.5, 1.5, -0.5), Vec3(0.5, 2.5, 0.5), 0.0};
  for (double inset : {0.0, 0.1}) {
    drawing.inset = inset;
    for (const Collider& c : everyShape()) {
      SCOPED_TRACE(std::string(colliderType(c)) + " inset " + std::to_string(inset));
      const SurfaceMesh mesh = surfaceMesh(c, drawing);
      ASSERT_FALSE(mesh.quads.empty());
      ASSERT_EQ(mesh.points.size(), mesh.normals.size());
      // A flat shape (its normal the same everywhere) is drawn at its surface: flat triangles
      // on it do not cut into it.
      const bool flat = std::all_of(mesh.normals.begin(), mesh.normals.end(),
                                    [&](const Vec3& n) { return n.isApprox(mesh.normals[0]); });
      for (std::size_t k = 0; k < mesh.points.size(); ++k) {
        EXPECT_NEAR(signedDistance(c, mesh.points[k]), flat ? 0.0 : -inset, 1e-12) << "point " << k;
        EXPECT_NEAR(mesh.normals[k].norm(), 1.0, 1e-12);
        EXPECT_GT(signedDistance(c, mesh.points[k] + 1e-3 * mesh.normals[k]),
                  signedDistance(c, mesh.points[k]));
      }
      for (const std::array<int, 4>& q : mesh.quads) {  // counter-clockwise seen from outside
        const Vec3 turn = (mesh.points[q[2]] - mesh.points[q[0]]).cross(mesh.points[q[3]] - mesh.points[q[1]]);
        EXPECT_GT(turn.dot(mesh.normals[q[0]] + mesh.normals[q[2]]), 0.0);
      }
    }
  }
}

TEST(ColliderDrawing, APlaneIsDrawnUnderTheMiddleOfWhatIsDrawnWithIt) {
  const Plane ground{Vec3(0, 1, 0), Vec3::UnitY(), 0.01};
  const SurfaceMesh mesh = surfaceMesh(ground, SurfaceDrawing{Vec3(2, 3, -1), Vec3(4, 5, 1), 0.0});
  Vec3 low = Vec3::Constant(1e9), high = Vec3::Constant(-1e9);
  for (const Vec3& p : mesh.points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  EXPECT_TRUE((0.5 * (low + high)).isApprox(Vec3(3, 1, 0)));  // below (3, 4, 0)
  // 1.2 times the diagonal of the 2 x 2 x 2 box wide: sqrt(12) * 1.2 across.
  EXPECT_NEAR(high.x() - low.x(), 1.2 * std::sqrt(12.0), 1e-12);
}

}  // namespace
}  // namespace mysim
