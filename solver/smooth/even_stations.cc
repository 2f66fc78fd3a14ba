#include "solver/smooth/even_stations.h"

#include <vector>

#include "model/path/rail_projection.h"

namespace tpopt {
namespace {

// Places poses first+1 .. last-1 of `out` at equal tip arc length along the
// moves of `path` between poses first and last.
void SpaceStretch(const ToolPath& path, const std::vector<JointVector>& joints,
                  const KinematicParams& kinematics, Interpolation interpolation, size_t first,
                  size_t last, ToolPath* out) {
  std::vector<double> s_mm(last - first + 1, 0.0);
  for (size_t i = first + 1; i <= last; ++i) {
    s_mm[i - first] =
        s_mm[i - 1 - first] + (path.poses[i].p_w_tip - path.poses[i - 1].p_w_tip).norm();
  }
  const double length_mm = s_mm.back();
  size_t move = first;  // the move move -> move + 1 holds the station
  for (size_t k = first + 1; k < last; ++k) {
    const double station_mm = length_mm * static_cast<double>(k - first) / (last - first);
    while (move + 1 < last && s_mm[move + 1 - first] < station_mm) ++move;
    const double move_mm = s_mm[move + 1 - first] - s_mm[move - first];
    const double lambda = move_mm > 0 ? (station_mm - s_mm[move - first]) / move_mm : 0.0;
    InterpolateMove<double>(kinematics, interpolation, joints[move], joints[move + 1],
                            path.poses[move].p_w_tip, path.poses[move + 1].p_w_tip, lambda,
                            &out->poses[k].p_w_tip, &out->poses[k].a_w);
    // Its joints are no longer those the program gave the block.
    out->poses[k].programmed.reset();
  }
}

}  // namespace

Status EvenStations(const ToolPath& path, const RuledSurface& surface, const Machine& machine,
                    Interpolation interpolation, ToolPath* out) {
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(path, &joints));
  const std::vector<double> u = ProjectPathOntoRail(surface.rail(0), path);
  const std::vector<bool> beyond = PosesBeyondRailEnds(surface.rail(0), path, u);
  *out = path;
  const size_t n = path.poses.size();
  // The move into pose i continues the stretch that pose i - 1 is in.
  const auto continues = [&](size_t i) {
    const ToolPose& pose = path.poses[i];
    return !IsPositioningMove(pose) && !beyond[i] && !beyond[i - 1] &&
           pose.tool == path.poses[i - 1].tool;
  };
  for (size_t first = 0; first < n;) {
    size_t last = first;
    while (last + 1 < n && continues(last + 1)) ++last;
    if (last >= first + 2) {
      SpaceStretch(path, joints, machine.kinematics, interpolation, first, last, out);
    }
    first = last + 1;
  }
  return Status::Ok();
}

}  // namespace tpopt
