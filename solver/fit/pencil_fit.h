// The seed-004 fit applied to pencil paths (model/path/pencil_path.h): each
// run's CL points (ball centres) are fitted with their exact tangents, the
// fitted spans and the straight segments are measured against the ideal CL
// curve, and a tool path is assembled.
#ifndef TPOPT_SOLVER_PENCIL_FIT_H_
#define TPOPT_SOLVER_PENCIL_FIT_H_

#include <vector>

#include "model/io/apt_io.h"
#include "model/path/pencil_path.h"
#include "model/path/tool_path.h"
#include "solver/fit/curve_output.h"
#include "solver/fit/span_error.h"

namespace tpopt {

struct PencilFitResult {
  // Tips (ball centre - radius * axis) along the tool axis; rapids retract
  // by kPencilClearanceMm between runs.
  ToolPath path;
  std::vector<AptCurveSpan> spans;  // empty unless fitting was asked for
  SpanErrors errors;                // worst over all runs
  size_t cl_points = 0;
  // CL points where the ball centre runs against the contact point: the
  // surface bends tighter than the ball along the path there, and the ball
  // gouges the surface beside the contact. The seed removes such points
  // before fitting (by a method it leaves to another paper); tpopt counts
  // them so that the command can warn.
  size_t folded_points = 0;
  size_t windows = 0;         // 4-point windows fitted
  double fit_seconds = 0.0;   // wall time of the window fits alone
};

constexpr double kPencilClearanceMm = 5.0;

// `runs[k]` belongs to `guides[k]`. Errors are measured at 15 samples of
// the ideal CL curve inside each span. With `write_spans` false the path
// holds the CL points only (straight moves) and `spans` stays empty; the
// errors are measured either way.
Status FitPencilRuns(const PencilGeometry& geometry, const std::vector<BSplineCurve>& guides,
                     const std::vector<PencilRun>& runs, double ball_radius_mm,
                     const CurveOutputOptions& options, bool write_spans,
                     PencilFitResult* result);

// The ideal CL curve of a run between its points i and i + 1, at fraction x
// of the guide parameter there (for MeasureSpanErrors).
IdealCurve IdealPencilCurve(const PencilGeometry& geometry, const BSplineCurve& guide,
                            const PencilRun& run);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_PENCIL_FIT_H_
