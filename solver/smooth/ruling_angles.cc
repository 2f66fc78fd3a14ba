#include "solver/smooth/ruling_angles.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

#include "model/machine/machine.h"

namespace tpopt {

std::vector<RulingReference> RulingAngles(const RuledSurface& surface, const std::vector<double>& u,
                                          const std::vector<bool>& beyond_ends,
                                          const std::vector<Eigen::Vector2d>& start_ac,
                                          double cone_deg, bool a_near_pole) {
  CHECK(u.size() == beyond_ends.size() && u.size() == start_ac.size());
  constexpr double kDeg = M_PI / 180.0;
  std::vector<RulingReference> angles(u.size());
  for (size_t i = 0; i < u.size(); ++i) {
    if (beyond_ends[i]) continue;
    const Eigen::Vector2d& start = start_ac[i];
    const Eigen::Vector3d start_axis = AnglesToAxis(start[0], start[1]);
    Eigen::Vector3d ruling = surface.Dv(u[i]).normalized();
    if (ruling.dot(start_axis) < 0) ruling = -ruling;
    const double axis_from_ruling = std::acos(std::min(1.0, ruling.dot(start_axis)));
    if (axis_from_ruling > cone_deg * kDeg) continue;
    const double ruling_from_pole = std::acos(std::min(1.0, std::abs(ruling.z())));
    const bool near_pole = ruling_from_pole < kRulingAnglesPoleDeg * kDeg;
    const bool a_clear_of_pole =
        a_near_pole && ruling_from_pole >= kRulingAPoleClearance * axis_from_ruling;
    if (near_pole && !a_clear_of_pole) continue;
    double nearest = INFINITY;
    for (const Eigen::Vector2d& branch : AxisToAngles(ruling)) {
      const double dc = std::remainder(branch[1] - start[1], 2 * M_PI);
      const double distance = std::abs(branch[0] - start[0]) + std::abs(dc);
      if (distance < nearest) {
        nearest = distance;
        angles[i].a = branch[0];
        if (!near_pole) angles[i].c = start[1] + dc;
      }
    }
  }
  return angles;
}

}  // namespace tpopt
