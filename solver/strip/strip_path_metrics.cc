#include "solver/strip/strip_path_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glog/logging.h>

namespace tpopt {

StripPathMetrics MeasureStripPath(const std::vector<StripPoint>& points) {
  CHECK_GE(points.size(), 3u);
  StripPathMetrics m;
  m.min_width_mm = std::numeric_limits<double>::infinity();
  m.worst_deviation_mm = std::numeric_limits<double>::infinity();
  m.max_deviation_in_strip_mm = -std::numeric_limits<double>::infinity();
  for (const StripPoint& p : points) {
    const double w = p.strip.width();
    m.mean_width_mm += w / points.size();
    m.min_width_mm = std::min(m.min_width_mm, w);
    m.max_width_mm = std::max(m.max_width_mm, w);
    m.truncated_strips += p.strip.truncated ? 1 : 0;
    m.worst_deviation_mm = std::min(m.worst_deviation_mm, p.strip.min_deviation);
    m.max_deviation_in_strip_mm =
        std::max(m.max_deviation_in_strip_mm, p.strip.max_deviation_in_strip);
    m.max_strip_mid_offset_mm = std::max(m.max_strip_mid_offset_mm, std::abs(p.strip.mid()));
  }
  double sum_squares = 0.0;
  for (size_t i = 1; i + 1 < points.size(); ++i) {
    const double centre =
        (points[i + 1].tool_centre - 2 * points[i].tool_centre + points[i - 1].tool_centre).norm();
    const double cc = (points[i + 1].cc - 2 * points[i].cc + points[i - 1].cc).norm();
    m.centre_fluctuation_max_mm = std::max(m.centre_fluctuation_max_mm, centre);
    m.cc_second_difference_max_mm = std::max(m.cc_second_difference_max_mm, cc);
    sum_squares += centre * centre;
  }
  m.centre_fluctuation_rms_mm = std::sqrt(sum_squares / (points.size() - 2));
  return m;
}

}  // namespace tpopt
