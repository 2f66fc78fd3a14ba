#include "solver/spline/overhang.h"

#include <glog/logging.h>

#include <algorithm>
#include <numeric>

#include "solver/spline/smoothing_spline.h"

namespace tpopt {

Status PoseOverhangs(const BSplineCurve& rail, const ToolPath& path,
                     const std::vector<double>& u,
                     std::vector<double>* overhang_mm) {
  CHECK_EQ(u.size(), path.poses.size());
  overhang_mm->assign(path.poses.size(), 0.0);
  for (size_t first = 0; first < path.poses.size();) {
    const size_t end = RunEnd(path, first);
    std::vector<double> index(end - first), heights(end - first);
    std::iota(index.begin(), index.end(), 0.0);
    for (size_t i = first; i < end; ++i) {
      heights[i - first] =
          (rail.Point(u[i]) - path.poses[i].p_w_tip).dot(path.poses[i].a_w);
    }
    if (heights.size() < 3) {
      std::copy(heights.begin(), heights.end(), overhang_mm->begin() + first);
    } else {
      SmoothingSpline fit;
      const Status s = SmoothingSpline::FitWithinTolerance(
          index, heights, {}, kOverhangNoiseMm, &fit);
      if (!s.ok())
        return Status::Error("overhang of poses " + std::to_string(first) +
                             "-" + std::to_string(end - 1) + ": " +
                             s.message());
      std::copy(fit.values().begin(), fit.values().end(),
                overhang_mm->begin() + first);
    }
    first = end;
  }
  for (double& h : *overhang_mm) h = std::max(h, 0.0);
  return Status::Ok();
}

}  // namespace tpopt
