// The free-form surface's JSON file (mm):
//  {"name", "units": "mm", "kind": "bspline_surface",
//   "cutter_side": "positive" | "negative", "degree_u": 3, "degree_v": 3,
//   "knots_u": [...], "knots_v": [...],
//   "control_points": [[[x, y, z], ...  one row per u index ...], ...]}
// control_points[i][j] is P_ij: i runs along u, j along v.
#ifndef TPOPT_MODEL_FREEFORM_SURFACE_JSON_H_
#define TPOPT_MODEL_FREEFORM_SURFACE_JSON_H_

#include <string>

#include "model/geometry/freeform_surface.h"
#include "model/base/status.h"

namespace tpopt {

// Reads the JSON above. Errors name the file and the field, index and value.
Status ReadFreeformSurfaceJson(const std::string& path, FreeformSurface* surface);

}  // namespace tpopt

#endif  // TPOPT_MODEL_FREEFORM_SURFACE_JSON_H_
