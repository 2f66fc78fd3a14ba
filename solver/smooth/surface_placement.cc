#include "solver/smooth/surface_placement.h"

#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <glog/logging.h>

#include "model/path/path_generator.h"
#include "model/path/rail_projection.h"
#include "solver/spline/overhang.h"

namespace tpopt {
bool BeyondRailEnd(const RuledSurface& surface, const ToolPose& pose, double u) {
  if (u > 0.0 && u < 1.0) return false;
  const auto c1 = surface.rail(0).Evaluate(u, 1);
  const Eigen::Vector3d x =
      pose.p_w_tip + (c1[0] - pose.p_w_tip).dot(pose.a_w) * pose.a_w;  // level with C1(u)
  const Eigen::Vector3d outward = (u <= 0.0 ? -1.0 : 1.0) * c1[1].normalized();
  return (x - c1[0]).dot(outward) > kBeyondRailEndMm;
}

Status PlaceOnSurface(const ToolPath& input, const RuledSurface& surface, const Cutter& cutter,
                      ToolPath* out) {
  CHECK(out != nullptr);
  const size_t n = input.poses.size();
  const std::vector<double> u = ProjectPathOntoRail(surface.rail(0), input);
  std::vector<double> overhang_mm;
  RETURN_IF_ERROR(PoseOverhangs(surface.rail(0), input, u, &overhang_mm));
  ToolPath placed = input;
  std::vector<bool> on_surface(n, false);
  for (size_t i = 0; i < n; ++i) {
    const ToolPose& pose = input.poses[i];
    if (IsPositioningMove(pose) || BeyondRailEnd(surface, pose, u[i])) continue;
    FlankPathOptions dpo;
    dpo.strategy = FlankStrategy::kDoublePointOffset;
    dpo.cutter_radius_mm = cutter.RadiusAt(overhang_mm[i]);
    dpo.taper_rad = cutter.taper_rad;
    ToolPose at_u;
    RETURN_IF_ERROR(FlankPoseAt(surface, dpo, u[i], &at_u));
    placed.poses[i].a_w = at_u.a_w;
    placed.poses[i].p_w_tip = at_u.p_w_tip - overhang_mm[i] * at_u.a_w;
    on_surface[i] = true;
  }
  // Each pose off the surface follows its nearest pose on it within its
  // cutting run (a rapid or link target starts a run and keeps its place).
  for (size_t i = 0; i < n; ++i) {
    if (on_surface[i] || IsPositioningMove(input.poses[i])) continue;
    size_t nearest = n;
    for (size_t j = i; j > 0 && nearest == n;) {
      if (IsPositioningMove(input.poses[j])) break;
      --j;
      if (on_surface[j]) nearest = j;
    }
    for (size_t j = i + 1; j < n && !IsPositioningMove(input.poses[j]); ++j) {
      if (on_surface[j]) {
        if (nearest == n || j - i < i - nearest) nearest = j;
        break;
      }
    }
    if (nearest == n) continue;
    const ToolPose& from = input.poses[nearest];
    const ToolPose& to = placed.poses[nearest];
    const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(from.a_w, to.a_w);
    placed.poses[i].a_w = (turn * input.poses[i].a_w).normalized();
    placed.poses[i].p_w_tip = to.p_w_tip + turn * (input.poses[i].p_w_tip - from.p_w_tip);
  }
  *out = std::move(placed);
  return Status::Ok();
}

}  // namespace tpopt
