#include "solver/strip/strip_path.h"

#include <sstream>

#include "model/base/invalid_field.h"

namespace tpopt {

bool StripPathOptions::IsValid(std::string* why) const {
  if (!posture.IsValid(why)) return false;
  std::string problem;
  if (poses < 3 || poses > 100000) {
    problem = InvalidField("--cc_points", poses, "in [3, 100000]");
  } else if (!(path_v >= 0.0 && path_v <= 1.0)) {
    problem = InvalidField("--path_v", path_v, "in [0, 1]");
  } else if (!(u_begin >= 0.0 && u_begin < u_end && u_end <= 1.0)) {
    std::ostringstream range;
    range << "[" << u_begin << ", " << u_end << "]";
    problem = "u range (u_begin, u_end) must satisfy 0 <= u_begin < u_end <= 1 (got " +
              range.str() + ")";
  } else if (samples_per_side < 10 || samples_per_side > 10000) {
    problem = InvalidField("--section_samples", samples_per_side, "in [10, 10000]");
  } else {
    return true;
  }
  if (why != nullptr) *why = problem;
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
