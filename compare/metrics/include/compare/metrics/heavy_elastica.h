#pragma once
// The clamped heavy elastica: an inextensible strip of length L and bending rigidity B (both per
// unit width), clamped horizontally at s = 0, free at s = L, under its own weight w per unit area.
// With theta(s) its slope below the horizontal, moment balance gives
//   B theta'' = -w (L - s) cos(theta),   theta(0) = 0,   theta'(L) = 0
// (Love, "A treatise on the mathematical theory of elasticity", sec. 263; Peirce 1930, "The
// handle of cloth as a measurable quantity", for cloth). In s / L it depends on one number, the
// load lambda = w L^3 / B. Solved by shooting on theta'(0): fourth-order Runge-Kutta over 20,000
// steps and the secant method on theta'(L) = 0, to 1e-12 of L in the tip (tested against the
// small-load limit w L^4 / (8 B) and against the standard's 41.5 degrees at lambda = 8.004).
namespace springcheck {

struct ElasticaTip {
  double drop = 0.0;          // below the clamp, in units of L
  double reach = 0.0;         // along the clamp's direction, in units of L
  double tip_angle = 0.0;     // theta(L), rad
  double chord_angle = 0.0;   // atan(drop / reach), rad: what the cantilever tester reads
  double clamp_curvature = 0.0;  // theta'(0) L
};
ElasticaTip heavyElastica(double load);

// Peirce's bending length from a cantilever of overhang l whose chord makes angle phi below the
// horizontal: c = l (cos(phi / 2) / (8 tan(phi)))^(1/3) (Peirce 1930, eq. for the "heavy
// elastica" in its linearised form). At phi = 41.5 degrees the factor is 1/2: ASTM D1388 and
// ISO 9073-7 read c = l / 2 there and flexural rigidity G = w c^3.
double peirceBendingLength(double overhang, double chord_angle);

}  // namespace springcheck
