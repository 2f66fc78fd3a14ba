// The seed-004 fit as an output form: the tip path of each cutting run is
// fitted span by span (solver/fit/bspline_fit.h) and written both as cubic span
// records and as points of those spans, densely resampled, for controllers
// without spline interpolation.
#ifndef TPOPT_SOLVER_CURVE_OUTPUT_H_
#define TPOPT_SOLVER_CURVE_OUTPUT_H_

#include <string>
#include <vector>

#include "model/io/apt_io.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"
#include "solver/fit/bspline_fit.h"

namespace tpopt {

struct CurveOutputOptions {
  LocalFitOptions fit;
  // Largest distance between resampled points along a span's chord, mm. > 0.
  double sample_step_mm = 0.1;
  // A run is also split where the tip path turns by more than this between
  // two moves, deg, in (0, 180]: a spline through a corner overshoots it.
  double corner_angle_deg = 45.0;
  bool IsValid(std::string* why) const;
};

// Appends the poses along spans[i] (from poses[i] to poses[i + 1]) to `out`
// after the run's first pose, which the caller has appended: for each span
// its interior samples, then poses[i + 1] itself, exactly. Between two poses
// the axis is interpolated linearly in the span parameter and normalised,
// and the feed is that of the move into poses[i + 1]. Records each span for
// the APT writer.
void AppendFittedRun(const std::vector<ToolPose>& poses, const std::vector<CubicSpan>& spans,
                     double sample_step_mm, ToolPath* out, std::vector<AptCurveSpan>* records);

// Fits every run of `in`: maximal chains of feed moves, split at rapids, links,
// corners and repeated points, with tangents estimated from the points
// (EstimateUnitTangents). Runs of fewer than 4 poses stay straight moves.
// Every input pose is written, in order, with its own values.
Status FitToolPathCurves(const ToolPath& in, const CurveOutputOptions& options, ToolPath* out,
                         std::vector<AptCurveSpan>* records);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_CURVE_OUTPUT_H_
