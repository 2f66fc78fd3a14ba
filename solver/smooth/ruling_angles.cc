#include "solver/smooth/ruling_angles.h"

#include <cmath>

#include <glog/logging.h>

#include "model/machine/machine.h"

namespace tpopt {

std::vector<std::optional<Eigen::Vector2d>> RulingAngles(const RuledSurface& surface,
                                                         const std::vector<double>& u,
                                                         const std::vector<bool>& beyond_ends,
                                                         const std::vector<Eigen::Vector2d>& start_ac,
                                                         double cone_deg) {
  CHECK(u.size() == beyond_ends.size() && u.size() == start_ac.size());
  constexpr double kDeg = M_PI / 180.0;
  std::vector<std::optional<Eigen::Vector2d>> angles(u.size());
  for (size_t i = 0; i < u.size(); ++i) {
    if (beyond_ends[i]) continue;
    const Eigen::Vector2d& start = start_ac[i];
    const Eigen::Vector3d start_axis = AnglesToAxis(start[0], start[1]);
    Eigen::Vector3d ruling = surface.Dv(u[i]).normalized();
    if (ruling.dot(start_axis) < 0) ruling = -ruling;
    if (std::abs(ruling.z()) > std::cos(kRulingAnglesPoleDeg * kDeg) ||
        ruling.dot(start_axis) < std::cos(cone_deg * kDeg)) {
      continue;
    }
    double nearest = INFINITY;
    for (const Eigen::Vector2d& branch : AxisToAngles(ruling)) {
      const double dc = std::remainder(branch[1] - start[1], 2 * M_PI);
      const double distance = std::abs(branch[0] - start[0]) + std::abs(dc);
      if (distance < nearest) {
        nearest = distance;
        angles[i] = Eigen::Vector2d(branch[0], start[1] + dc);
      }
    }
  }
  return angles;
}

}  // namespace tpopt
