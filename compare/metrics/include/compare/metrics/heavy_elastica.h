#pragma once
// The clamped heavy elastica: an inextensible strip of length L and bending rigidity B (both per
// unit width), clamped horizontally at s = 0, free at s = L, under its own weight w per unit area.
// With theta(s) its slope below the horizontal, moment balance gives
//   B theta'' = -w (L - s) cos(theta),   theta(0) = 0,   theta'(L) = 0
// (Love, "A treatise on the mathematical theory of elasticity", sec. 263; Peirce 1930, "The
// handle of cloth as a measurable quantity", for cloth). In s / L it depends on one number, the
// load lambda = w L^3 / B. Solved by shooting on theta'(0): fourth-order Runge-Kutta over 5,000
// steps and regula falsi on theta'(L) = 0, to 1e-12 of L in the tip (heavier than load 30: from the
// tip, below) (tested against the
// small-load limit w L^4 / (8 B) and against the standard's 41.5 degrees at lambda = 8.004).
namespace springcheck {

// Up to this load (chords up to 68 degrees) the elastica is shot from the clamp on a bracket
// that holds one solution; above it the bracket holds curled-back roots too (load 50 found a
// 0.016 L drop), so heavier strips are shot from the free end in the tail's tilt, which stays
// well-conditioned at any load (heavy_elastica.cpp; tested against the large-load limit
// theta'(0) -> sqrt(2 load), reach -> sqrt(2 / load)).
constexpr double kMaxElasticaLoad = 30.0;
// The cantilever reference is solved up to this load (w L^3 / B = 1e6: the strip hangs straight
// down within 0.2 % of L below a bend a thousandth of L long; its integration then takes 1e6
// steps, about a second); heavier strips have no reference, and the reading says so.
constexpr double kLargestElasticaLoad = 1e6;
// A chord is read as a bending length up to the chord of this load (89.2 degrees): steeper
// chords tell loads apart by less than the reading's own error.
constexpr double kLargestReadableLoad = 1e4;

struct ElasticaTip {
  double drop = 0.0;          // below the clamp, in units of L
  double reach = 0.0;         // along the clamp's direction, in units of L
  double tip_angle = 0.0;     // theta(L), rad
  double chord_angle = 0.0;   // atan(drop / reach), rad: what the cantilever tester reads
  double clamp_curvature = 0.0;  // theta'(0) L
};
ElasticaTip heavyElastica(double load);

// The bending length c = (B / w)^(1/3) a cantilever of overhang l reads when its chord makes
// angle phi below the horizontal: the load whose elastica has that chord (bisection, the chord
// grows with the load), c = l / load^(1/3). At phi = 41.5 degrees this is the standard's own
// reading, c = l / 2 (ASTM D1388, ISO 9073-7; G = w c^3), within 0.02 %; at other angles it is
// what the standard's reading would be had the strip been slid out to 41.5 degrees. Peirce's
// closed approximation l (cos(phi / 2) / (8 tan phi))^(1/3) is 1.9 % above it at 41.5 degrees.
double bendingLengthFromChord(double overhang, double chord_angle);

}  // namespace springcheck
