// The heavy elastica (compare/metrics/heavy_elastica.h) and the cantilever reading: against the
// linear beam, the cantilever standard's 41.5 degrees, and its own boundary condition.
// ctest-label: unit,physics
#include "compare/metrics/heavy_elastica.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace springcheck {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Small loads: the linear beam's tip drop w L^4 / (8 B), that is load / 8 in units of L, with
// the first nonlinear correction O(load^3): within 1e-6 relative at load 1e-3.
TEST(HeavyElastica, ASmallLoadDropsAsTheLinearBeam) {
  const ElasticaTip tip = heavyElastica(1e-3);
  EXPECT_NEAR(tip.drop / (1e-3 / 8.0), 1.0, 1e-6);
  EXPECT_NEAR(tip.clamp_curvature / (1e-3 / 2.0), 1.0, 1e-6);  // M(0) = w L^2 / 2
  EXPECT_NEAR(tip.tip_angle / (1e-3 / 6.0), 1.0, 1e-6);        // w L^3 / (6 B)
}

// The standard reads the bending length where the chord from the clamp's edge to the tip makes
// 41.5 degrees, and c = l / 2 there: the elastica reaches that chord at load 8.004 (Peirce's
// analysis; the value the cantilever method rests on), within 0.02 % in c.
TEST(HeavyElastica, TheChordReachesTheStandardsAngleAtLoadEight) {
  const ElasticaTip tip = heavyElastica(8.004);
  EXPECT_NEAR(tip.chord_angle / kDegree, 41.5, 0.05);
  EXPECT_NEAR(bendingLengthFromChord(1.0, 41.5 * kDegree), 0.5, 1e-4);
  // And the reading inverts the elastica: the chord of load 3 reads 3^(-1/3) back, to 1e-9.
  EXPECT_NEAR(bendingLengthFromChord(1.0, heavyElastica(3.0).chord_angle), std::cbrt(1.0 / 3.0),
              1e-9);
}

// The strip is inextensible: the tip lies within L of the clamp, ever closer as the load grows,
// and the drop grows monotonically with the load.
TEST(HeavyElastica, TheTipStaysOnTheStripsLengthAndFallsFurtherUnderMoreLoad) {
  double last_drop = 0.0;
  for (double load : {0.5, 2.0, 8.0, 20.0, kMaxElasticaLoad}) {
    const ElasticaTip tip = heavyElastica(load);
    EXPECT_LT(std::hypot(tip.drop, tip.reach), 1.0);
    EXPECT_GT(tip.drop, last_drop) << load;
    EXPECT_LT(tip.tip_angle, std::numbers::pi / 2) << load;
    last_drop = tip.drop;
  }
}

// Any load, not only the bracket's (up to 30): the hanging branch followed by continuation. Drop
// and chord keep growing with the load past 30 (a strip at load 30.15 has a reference too), and a
// very heavy strip hangs straight down from a bend at the clamp whose closed form is the elastica
// under its whole weight as tension: theta'' = -load cos(theta) there, so theta'(0) -> sqrt(2 load)
// and the reach -> sqrt(2 / load) (first integral theta'^2 / 2 = load (1 - sin theta)); the
// corrections are O(load^(-1/2)), 1 % at load 1e4.
TEST(HeavyElastica, AnyLoadHasAReferenceAndAVeryHeavyStripHangsFromItsClampBend) {
  double last_drop = heavyElastica(kMaxElasticaLoad).drop;
  double last_chord = heavyElastica(kMaxElasticaLoad).chord_angle;
  for (double load : {30.15, 40.0, 100.0, 1e3, 1e4}) {
    const ElasticaTip tip = heavyElastica(load);
    EXPECT_GT(tip.drop, last_drop) << load;
    EXPECT_GT(tip.chord_angle, last_chord) << load;
    EXPECT_LT(tip.chord_angle, std::numbers::pi / 2) << load;
    EXPECT_LT(std::hypot(tip.drop, tip.reach), 1.0) << load;
    last_drop = tip.drop;
    last_chord = tip.chord_angle;
  }
  const ElasticaTip heavy = heavyElastica(1e4);
  EXPECT_NEAR(heavy.clamp_curvature / std::sqrt(2e4), 1.0, 0.02);
  EXPECT_NEAR(heavy.reach / std::sqrt(2.0 / 1e4), 1.0, 0.05);
  // The reading inverts it there too: the chord of load 200 reads 200^(-1/3) back.
  EXPECT_NEAR(bendingLengthFromChord(1.0, heavyElastica(200.0).chord_angle), std::cbrt(1.0 / 200.0),
              1e-7);
  // Continuous across the bracket's limit: 30 and 30 (1 + 1e-9) agree to 1e-8.
  EXPECT_NEAR(heavyElastica(kMaxElasticaLoad * (1 + 1e-9)).drop,
              heavyElastica(kMaxElasticaLoad).drop, 1e-8);
}

}  // namespace
}  // namespace springcheck
