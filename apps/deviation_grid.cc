#include "apps/deviation_grid.h"

namespace tpopt {

std::optional<SurfaceGrid> DeviationGridOf(const PathMetrics& metrics) {
  if (!metrics.deviation) return std::nullopt;
  const DeviationReport& d = *metrics.deviation;
  if (d.u.empty() || d.v.empty() || d.deviation_mm.size() != d.u.size() * d.v.size()) {
    return std::nullopt;
  }
  return SurfaceGrid{d.u, d.v, d.deviation_mm};
}

}  // namespace tpopt
