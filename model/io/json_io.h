// Readers of the surface and machine JSON files (docs/ARCHITECTURE.md, "File formats").
// Every error names the file, and the key, index and value at fault.
#ifndef TPOPT_MODEL_JSON_IO_H_
#define TPOPT_MODEL_JSON_IO_H_

#include <string>

#include <vector>

#include "model/geometry/bspline_curve.h"
#include "model/geometry/bspline_surface.h"
#include "model/machine/machine.h"
#include "model/path/pencil_path.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"

namespace tpopt {

// {"name", "units": "mm", "kind": "ruled", "cutter_side": "positive" |
// "negative", "rails": [{degree, knots, control_points}, {...}]}.
Status ReadSurfaceJson(const std::string& path, RuledSurface* surface);

// {"name", "kinematics": "xyzac-trt", "rotary_pivot": [x, y, z], "y_offset",
// "z_offset", "tool_length", "axes": {"X": {min, max, max_velocity,
// max_acceleration, max_jerk}, ...}}: mm and degrees in the file, radians
// inside. Absent keys mean no limit (or 0 for the offsets).
Status ReadMachineJson(const std::string& path, Machine* machine);

// {"name", "units": "mm", "kind": "bspline_surface", "degree_u", "degree_v"
// (1..3), "knots_u", "knots_v", "control_points": [[[x, y, z], ...], ...]}
// with control_points[i][j], i along u.
Status ReadBSplineSurfaceJson(const std::string& path, BSplineSurface* surface);

// Planar guide curves for a pencil path: {"name", "units": "mm", "kind":
// "planar_curves", "placement": {"anchor_uv": [u, v], "lift_mm",
// "spin_deg"} (each optional, GuidePlacement's defaults), "curves":
// [{"degree", "knots", "control_points": [[x, y], ...]}, ...]}. The curves
// come back in the plane z = 0.
Status ReadGuideCurvesJson(const std::string& path, std::vector<BSplineCurve>* curves,
                           GuidePlacement* placement);

}  // namespace tpopt

#endif  // TPOPT_MODEL_JSON_IO_H_
