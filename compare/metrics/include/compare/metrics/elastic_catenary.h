#pragma once
// The continuous elastic catenary (Irvine, "Cable structures", 1981, ch. 2): a cable of
// unstretched length L0, weight w per unstretched length and axial stiffness EA hung between two
// level supports a span D apart. With H the horizontal tension and V = w L0 / 2 the vertical
// reaction at each support, the point at unstretched arc length s lies at
//   x(s) = H s / EA + (H / w) [asinh(V / H) - asinh((V - w s) / H)]
//   y(s) = (V s - w s^2 / 2) / EA + (H / w) [sqrt(1 + (V / H)^2) - sqrt(1 + ((V - w s) / H)^2)]
// (y downward), and H solves x(L0) = D. It is the limit of the discrete elastic catenary
// (closed_form.h) as the chain's links shrink: N links of rest L0 / N, stiffness EA N / L0 and
// masses w L0 / (N g) converge to it at second order (tested).
namespace springcheck {

struct ElasticCatenary {
  double horizontal_tension = 0.0;  // H, N
  double midspan_sag = 0.0;         // y(L0 / 2), m below the supports
};

// Nothing (H = 0) if the span is not less than the cable could reach: D >= L0 + stretch.
ElasticCatenary levelElasticCatenary(double span, double length, double weight, double axial);

}  // namespace springcheck
