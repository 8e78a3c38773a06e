#pragma once
// Distances between a mesh's own pieces, for self-collision (self_collision.h) and for the
// metrics that judge it in every engine (self_intersections, self_distance_min).
#include "mysim/types.h"

namespace mysim {

// The point of triangle (a, b, c) nearest to p, as barycentric weights (w_a, w_b, w_c), each in
// [0, 1], summing to 1 (Ericson, "Real-Time Collision Detection", 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// The nearest points of segments p0-p1 and q0-q1, as p0 + s (p1 - p0) and q0 + t (q1 - q0),
// s and t in [0, 1] (Ericson 5.1.9; a degenerate segment is its point).
struct SegmentParameters {
  double s = 0.0, t = 0.0;
};
SegmentParameters closestOnSegments(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

// Whether segment p0-p1 crosses triangle (a, b, c) (touching counts; a segment in the
// triangle's plane does not, which two crossing triangles never need: another of their six
// edges crosses).
bool segmentCrossesTriangle(const Vec3& p0, const Vec3& p1, const Vec3& a, const Vec3& b, const Vec3& c);

// Whether two triangles that share no vertex intersect: one's edge crosses the other.
bool trianglesIntersect(const Vec3 (&first)[3], const Vec3 (&second)[3]);

}  // namespace mysim
