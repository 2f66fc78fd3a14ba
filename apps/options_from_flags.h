// Options structs filled from the flags, validated: one place for the
// mapping so that every subcommand reads a flag the same way.
#ifndef TPOPT_APPS_OPTIONS_FROM_FLAGS_H_
#define TPOPT_APPS_OPTIONS_FROM_FLAGS_H_

#include "model/machine/axis_metrics.h"
#include "model/eval/deviation.h"
#include "model/path/link_moves.h"
#include "model/base/status.h"
#include "solver/smooth/ceres_smoother.h"
#include "solver/fit/curve_output.h"
#include "solver/spline/spline_smoother.h"

namespace tpopt {

Status MetricOptionsFromFlags(DeviationOptions* deviation, MotionOptions* motion);

Status LinkMoveOptionsFromFlags(LinkMoveOptions* links);

// Without a surface (surface_free), the high-accuracy weights the command
// line leaves at their flag defaults take HighAccuracyOptions::SurfaceFree()'s
// values instead, so that a run without the preset works.
Status SmootherOptionsFromFlags(bool surface_free, SplineSmootherOptions* spline,
                                HighAccuracyOptions* high_accuracy);

// --output_curve (bspline or not), --curve_step_mm and the --fit_* flags;
// errors are usage errors.
Status CurveOutputOptionsFromFlags(bool* bspline, CurveOutputOptions* options);

}  // namespace tpopt

#endif  // TPOPT_APPS_OPTIONS_FROM_FLAGS_H_
