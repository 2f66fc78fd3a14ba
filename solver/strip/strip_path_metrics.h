// What a strip-width pass achieves: strip widths, the deviation across the
// strips, and the tool-centre fluctuation the seed (Chen, Yue, Xu 2011)
// sets out to reduce.
#ifndef TPOPT_SOLVER_STRIP_PATH_METRICS_H_
#define TPOPT_SOLVER_STRIP_PATH_METRICS_H_

#include <vector>

#include "solver/strip/strip_path.h"

namespace tpopt {

struct StripPathMetrics {
  // Strip width over the CC points, mm.
  double mean_width_mm = 0.0, min_width_mm = 0.0, max_width_mm = 0.0;
  // CC points whose strip reached the end of the sampled cross section.
  int truncated_strips = 0;
  // Least deviation anywhere on the sampled sections (< 0: gouge) and the
  // largest inside any strip, mm.
  double worst_deviation_mm = 0.0;
  double max_deviation_in_strip_mm = 0.0;
  // Largest |mid-point of the strip - CC point| along the cross direction.
  double max_strip_mid_offset_mm = 0.0;
  // Tool-centre fluctuation: |c[i+1] - 2 c[i] + c[i-1]| over interior CC
  // points, max and RMS, mm; and the same of the CC points themselves, the
  // part any method inherits from the curve.
  double centre_fluctuation_max_mm = 0.0, centre_fluctuation_rms_mm = 0.0;
  double cc_second_difference_max_mm = 0.0;
};

// Precondition: at least 3 points.
StripPathMetrics MeasureStripPath(const std::vector<StripPoint>& points);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_STRIP_PATH_METRICS_H_
