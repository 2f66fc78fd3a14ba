#include "solver/spline/pole_passage.h"

#include <cmath>

#include "model/machine/machine.h"

namespace tpopt {
namespace {

// The polar angle of an axis from +Z and its azimuth, as the machine's A
// and C on the A >= 0 branch.
Eigen::Vector2d PolarAndAzimuth(const Eigen::Vector3d& a_w) {
  return AxisToAngles(a_w)[0];
}

// `angle` moved by whole turns to within half a turn of `near`.
double UnwrapNear(double angle, double near) {
  return angle + 2.0 * M_PI * std::round((near - angle) / (2.0 * M_PI));
}

// Unwrapped azimuths of poses first..last; straight over the pole, where
// the machine holds C because the azimuth is undefined (its singularity
// rule), the previous one carries on.
std::vector<double> UnwrappedAzimuths(const ToolPath& path, size_t first,
                                      size_t last) {
  std::vector<double> azimuth;
  azimuth.reserve(last - first + 1);
  double previous = PolarAndAzimuth(path.poses[first].a_w)[1];
  for (size_t i = first; i <= last; ++i) {
    const Eigen::Vector2d angles = PolarAndAzimuth(path.poses[i].a_w);
    if (std::sin(angles[0]) >= Machine::kSingularSinA) {
      previous = UnwrapNear(angles[1], previous);
    }
    azimuth.push_back(previous);
  }
  return azimuth;
}

}  // namespace

std::vector<PolePassage> FindPolePassages(const ToolPath& path,
                                          double pole_angle_rad) {
  std::vector<PolePassage> passages;
  const size_t n = path.poses.size();
  size_t i = 0;
  while (i < n) {
    if (PolarAndAzimuth(path.poses[i].a_w)[0] >= pole_angle_rad) {
      ++i;
      continue;
    }
    size_t last = i;
    while (last + 1 < n && !IsPositioningMove(path.poses[last + 1]) &&
           PolarAndAzimuth(path.poses[last + 1].a_w)[0] < pole_angle_rad) {
      ++last;
    }
    const std::vector<double> azimuth = UnwrappedAzimuths(path, i, last);
    const double sweep = azimuth.back() - azimuth.front();
    if (std::abs(sweep) >= M_PI / 2) passages.push_back({i, last, sweep});
    i = last + 1;
  }
  return passages;
}

ToolPath RerouteAroundPole(const ToolPath& path, const PolePassage& passage,
                           const Cutter& cutter) {
  ToolPath out = path;
  const std::vector<double> azimuth =
      UnwrappedAzimuths(path, passage.first, passage.last);
  const double sweep = passage.azimuth_sweep_rad;
  const double other_way = sweep - std::copysign(2.0 * M_PI, sweep);
  const double scale = other_way / sweep;
  const double pivot_height = 0.5 * cutter.flute_length_mm;
  for (size_t i = passage.first; i <= passage.last; ++i) {
    ToolPose& pose = out.poses[i];
    const double polar = PolarAndAzimuth(pose.a_w)[0];
    const double turned =
        azimuth.front() +
        (azimuth[i - passage.first] - azimuth.front()) * scale;
    const Eigen::Vector3d axis = AnglesToAxis<double>(polar, turned);
    pose.p_w_tip += pivot_height * (pose.a_w - axis);
    pose.a_w = axis;
  }
  return out;
}

}  // namespace tpopt
