// Options structs filled from the flags, validated: one place for the
// mapping so that every subcommand reads a flag the same way.
#ifndef TPOPT_APPS_OPTIONS_FROM_FLAGS_H_
#define TPOPT_APPS_OPTIONS_FROM_FLAGS_H_

#include "model/axis_metrics.h"
#include "model/deviation.h"
#include "model/status.h"
#include "solver/ceres_smoother.h"
#include "solver/spline_smoother.h"

namespace tpopt {

Status MetricOptionsFromFlags(DeviationOptions* deviation, MotionOptions* motion);

Status SmootherOptionsFromFlags(SplineSmootherOptions* spline, HighAccuracyOptions* high_accuracy);

}  // namespace tpopt

#endif  // TPOPT_APPS_OPTIONS_FROM_FLAGS_H_
