// A strip-width machining pass: cutter-contact (CC) points along the
// iso-parametric curve v = const of a surface, each positioned by one of the
// methods of solver/strip/tool_posture.h.
#ifndef TPOPT_SOLVER_STRIP_PATH_H_
#define TPOPT_SOLVER_STRIP_PATH_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/geometry/parametric_surface.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"
#include "solver/strip/tool_posture.h"

namespace tpopt {

struct StripPathOptions {
  PostureMethod method = PostureMethod::kMidPointErrorControl;
  PostureOptions posture;
  // CC points, evenly spaced in u over [u_begin, u_end] at v = path_v. >= 3.
  int poses = 60;
  double path_v = 0.5;
  double u_begin = 0.05, u_end = 0.95;
  // Cross-section samples each side of the CC point, over 2 R.
  int samples_per_side = 120;

  bool IsValid(std::string* why) const;
};

struct StripPoint {
  double u = 0.0, v = 0.0;
  Eigen::Vector3d cc = Eigen::Vector3d::Zero();
  Posture posture;
  PlacedTool tool;
  Eigen::Vector3d tool_centre = Eigen::Vector3d::Zero();  // tip + r axis
  Strip strip;
};

// Positions the cutter at every CC point. Fails, naming the CC index and
// (u, v), where the surface is degenerate.
Status PlanStripPath(const ParametricSurface& surface, const TorusCutter& cutter,
                     const StripPathOptions& options, std::vector<StripPoint>* points);

// The pass as CL poses (tip, axis) at `feed_mm_per_min`, cutter R as its
// radius (APT's TLDATA carries no corner radius; it is in the title).
ToolPath StripPathToToolPath(const std::vector<StripPoint>& points, const TorusCutter& cutter,
                             double feed_mm_per_min, const std::string& title);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_STRIP_PATH_H_
