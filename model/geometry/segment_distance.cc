#include "model/geometry/segment_distance.h"

#include <algorithm>

namespace tpopt {

double DistanceToSegment(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t =
      len2 > 0.0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (q - a - t * ab).norm();
}

}  // namespace tpopt
