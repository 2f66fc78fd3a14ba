#include "solver/strip_path.h"

#include <sstream>

namespace tpopt {

bool StripPathOptions::IsValid(std::string* why) const {
  std::ostringstream err;
  if (!posture.IsValid(why)) return false;
  if (poses < 3 || poses > 100000) {
    err << "poses = " << poses << " must be in [3, 100000]";
  } else if (!(path_v >= 0.0 && path_v <= 1.0)) {
    err << "path v = " << path_v << " must be in [0, 1]";
  } else if (!(u_begin >= 0.0 && u_begin < u_end && u_end <= 1.0)) {
    err << "u range [" << u_begin << ", " << u_end << "] must satisfy 0 <= begin < end <= 1";
  } else if (samples_per_side < 10 || samples_per_side > 10000) {
    err << "samples per side = " << samples_per_side << " must be in [10, 10000]";
  } else {
    return true;
  }
  if (why != nullptr) *why = err.str();
  return false;
}

Status PlanStripPath(const ParametricSurface& surface, const TorusCutter& cutter,
                     const StripPathOptions& options, std::vector<StripPoint>* points) {
  points->assign(options.poses, StripPoint());
  for (int i = 0; i < options.poses; ++i) {
    StripPoint& p = (*points)[i];
    p.u = options.u_begin + (options.u_end - options.u_begin) * i / (options.poses - 1);
    p.v = options.path_v;
    const Eigen::Vector3d feed = surface.Evaluate(p.u, p.v).su;
    CrossSection section;
    const Status s = BuildCrossSection(surface, p.u, p.v, feed, 2.0 * cutter.radius_mm,
                                       options.samples_per_side, &section);
    if (!s.ok()) return Status::Error("CC point " + std::to_string(i) + ": " + s.message());
    p.cc = section.cc;
    const Posture* previous = i > 0 ? &(*points)[i - 1].posture : nullptr;
    p.posture =
        ChoosePosture(options.method, cutter, section, options.posture, &p.strip, previous);
    p.tool = PlaceTool(cutter, section, p.posture);
    p.tool_centre = ToolCentre(cutter, p.tool.tip, p.tool.axis);
  }
  return Status::Ok();
}

ToolPath StripPathToToolPath(const std::vector<StripPoint>& points, const TorusCutter& cutter,
                             double feed_mm_per_min, const std::string& title) {
  ToolPath path;
  path.title = title;
  Cutter as_written;
  as_written.radius_mm = cutter.radius_mm;
  as_written.flute_length_mm = 4.0 * cutter.radius_mm;
  path.cutter = as_written;
  for (const StripPoint& p : points) {
    ToolPose pose;
    pose.p_w_tip = p.tool.tip;
    pose.a_w = p.tool.axis;
    pose.feed_mm_per_min = feed_mm_per_min;
    path.poses.push_back(pose);
  }
  return path;
}

}  // namespace tpopt
