// The deviation map of a path as a plain grid over the surface's (u, v).
// The one place the pictures (HTML report, VTK export) read the deviation
// evaluator's output, so a change of model/eval/deviation.h touches only this.
#ifndef TPOPT_APPS_DEVIATION_GRID_H_
#define TPOPT_APPS_DEVIATION_GRID_H_

#include <optional>
#include <vector>

#include "model/eval/path_metrics.h"

namespace tpopt {

struct SurfaceGrid {
  std::vector<double> u, v;  // increasing, in [0, 1]
  // Signed deviation, mm, row-major deviation_mm[iu * v.size() + iv]:
  // negative is overcut (gouge), positive undercut (material left).
  std::vector<double> deviation_mm;
};

// The grid the metrics were evaluated on; empty without a surface.
std::optional<SurfaceGrid> DeviationGridOf(const PathMetrics& metrics);

}  // namespace tpopt

#endif  // TPOPT_APPS_DEVIATION_GRID_H_
