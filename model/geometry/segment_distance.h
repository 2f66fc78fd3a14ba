// The distance from a point to a straight segment, the one shared helper for
// the swept-envelope deviation (model/eval/deviation.cc) and the chord error of
// CL segments (solver/fit/span_error.cc).
#ifndef TPOPT_MODEL_SEGMENT_DISTANCE_H_
#define TPOPT_MODEL_SEGMENT_DISTANCE_H_

#include <Eigen/Core>

namespace tpopt {

// Distance from q to the closed segment [a, b], in the points' unit (mm).
// A degenerate segment (a == b) is the point a.
double DistanceToSegment(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b);

}  // namespace tpopt

#endif  // TPOPT_MODEL_SEGMENT_DISTANCE_H_
