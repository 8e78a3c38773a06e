// Cloth topology, normals and mesh export.
// ctest-label: unit
#include "mysim/cloth.h"

#include <gtest/gtest.h>

#include <sstream>

#include "mysim/cloth_surface.h"

namespace mysim {
namespace {

ClothShape shape(int rows, int cols) {
  ClothShape s;
  s.rows = rows;
  s.cols = cols;
  s.width = 2.0;
  s.height = 1.0;
  s.structural = SpringParameters{10, 0};
  s.shear = SpringParameters{5, 0};
  s.flex = SpringParameters{1, 0};
  return s;
}

std::array<long, 5> countFamilies(const Model& m) {
  std::array<long, 5> n{};
  for (const Spring& s : m.springs) ++n[static_cast<int>(s.family)];
  return n;
}

TEST(ClothTopology, SpringCountsPerFamilyMatchHandCountOnA3x4Grid) {
  // 3 rows x 4 cols:  structural 3*3 + 4*2 = 17,  shear 2 * 2*3 = 12,  flex 3*2 + 4*1 = 10.
  Model m;
  buildCloth(shape(3, 4), m);
  const auto n = countFamilies(m);
  EXPECT_EQ(n[int(SpringFamily::Structural)], 17);
  EXPECT_EQ(n[int(SpringFamily::Shear)], 12);
  EXPECT_EQ(n[int(SpringFamily::Flex)], 10);
  EXPECT_EQ(m.particleCount(), 12);
}

TEST(ClothTopology, SpringCountsMatchTheFormulaForManyGrids) {
  for (auto [r, c] : {std::pair{2, 2}, {2, 7}, {14, 14}, {5, 9}, {30, 3}}) {
    Model m;
    buildCloth(shape(r, c), m);
    const auto n = countFamilies(m);
    const ClothSpringCounts e = expectedClothSpringCounts(r, c);
    EXPECT_EQ(n[int(SpringFamily::Structural)], e.structural) << r << "x" << c;
    EXPECT_EQ(n[int(SpringFamily::Shear)], e.shear);
    EXPECT_EQ(n[int(SpringFamily::Flex)], e.flex);
  }
}

TEST(ClothTopology, RestLengthsAreGridSpacingsAndAbsentFamiliesAddNothing) {
  ClothShape s = shape(5, 9);  // spacing 0.25 both ways
  s.shear.reset();
  Model m;
  buildCloth(s, m);
  for (const Spring& sp : m.springs) {
    const double expected = sp.family == SpringFamily::Flex ? 0.5 : 0.25;
    EXPECT_NEAR(sp.rest_length, expected, 1e-12);
    EXPECT_NE(sp.family, SpringFamily::Shear);
  }
}

TEST(ClothNormals, FlatSheetNormalsAreUnitAndPerpendicular) {
  Model m;
  buildCloth(shape(4, 5), m);  // horizontal: in the x-z plane
  for (const Vec3& n : vertexNormals(*m.grid, m.start_position)) {
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(n.y()), 1.0, 1e-12);
  }
}

TEST(ClothNormals, VertexNormalIsTheNormalisedSumOfItsFaceNormals) {
  // Fold a 2 x 3 sheet along its middle column: the fold vertices' normals bisect the two faces.
  ClothShape s = shape(2, 3);
  s.width = 2.0;
  Model m;
  buildCloth(s, m);
  Vector x = m.start_position;
  for (int r = 0; r < 2; ++r) x[3 * (r * 3 + 2) + 1] = 1.0;  // lift the right column by 1 m
  const auto normals = vertexNormals(*m.grid, x);
  // Left cell: flat, normal (0, 1, 0). Right cell: plane rising 1 m over 1 m in x, normal
  // (-1, 1, 0) / sqrt 2. A middle vertex touches faces of both cells.
  const Vec3 left(0, 1, 0), right = Vec3(-1, 1, 0).normalized();
  // Vertex 1 (row 0, middle) lies on triangles (0,1,3) and (1,4,3) of the left cell and
  // (1,2,4) of the right one.
  const Vec3 expected_top = (2 * left + right).normalized();
  EXPECT_TRUE(normals[1].isApprox(expected_top, 1e-12)) << normals[1].transpose();
}

TEST(ClothMesh, ObjHasOneVertexAndNormalPerParticleAndTwoFacesPerCell) {
  Model m;
  buildCloth(shape(3, 4), m);
  std::ostringstream out;
  writeObj(out, *m.grid, m.start_position);
  std::istringstream in(out.str());
  int v = 0, vn = 0, f = 0;
  for (std::string line; std::getline(in, line);) {
    v += line.rfind("v ", 0) == 0;
    vn += line.rfind("vn ", 0) == 0;
    f += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(v, 12);
  EXPECT_EQ(vn, 12);
  EXPECT_EQ(f, 2 * 2 * 3);
}

}  // namespace
}  // namespace mysim
