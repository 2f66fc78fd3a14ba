// Options structs filled from the flags, validated: one place for the
// mapping so that every subcommand reads a flag the same way.
#ifndef TPOPT_APPS_OPTIONS_FROM_FLAGS_H_
#define TPOPT_APPS_OPTIONS_FROM_FLAGS_H_

#include "model/machine/axis_metrics.h"
#include "model/eval/deviation.h"
#include "model/path/link_moves.h"
#include "model/path/path_generator.h"
#include "model/path/pencil_path.h"
#include "model/cutter/torus_cutter.h"
#include "model/base/status.h"
#include "solver/smooth/ceres_smoother.h"
#include "solver/fit/curve_output.h"
#include "solver/smooth/feed_scheduler.h"
#include "solver/spline/spline_smoother.h"
#include "solver/strip/strip_path.h"

namespace tpopt {

Status MetricOptionsFromFlags(DeviationOptions* deviation, MotionOptions* motion);

// --feed, --feed_mode and the limits on raised feeds; errors are usage
// errors.
Status FeedScheduleOptionsFromFlags(FeedScheduleOptions* feed);

Status LinkMoveOptionsFromFlags(LinkMoveOptions* links);

// Without a surface (surface_free), the high-accuracy weights the command
// line leaves at their flag defaults take HighAccuracyOptions::SurfaceFree()'s
// values instead, so that a run without the preset works.
Status SmootherOptionsFromFlags(bool surface_free, SplineSmootherOptions* spline,
                                HighAccuracyOptions* high_accuracy);

// --output_curve (bspline or not), --curve_step_mm and the --fit_* flags;
// errors are usage errors.
Status CurveOutputOptionsFromFlags(bool* bspline, CurveOutputOptions* options);

// generate: --strategy, --cutter_radius (required) and the path's flags.
Status FlankPathOptionsFromFlags(FlankPathOptions* options);

// pencil: --ball_radius, --feed, --interpolation_period_ms.
Status PencilOptionsFromFlags(PencilOptions* pencil);

// stripwidth: --cutter=torus:R,r, --method and the posture's flags, --feed.
Status StripPathOptionsFromFlags(TorusCutter* cutter, StripPathOptions* options);

}  // namespace tpopt

#endif  // TPOPT_APPS_OPTIONS_FROM_FLAGS_H_
