// Readers of the surface and machine JSON files (DESIGN.md, "File formats").
// Every error names the file, and the key, index and value at fault.
#ifndef TPOPT_MODEL_JSON_IO_H_
#define TPOPT_MODEL_JSON_IO_H_

#include <string>

#include "model/machine.h"
#include "model/ruled_surface.h"
#include "model/status.h"

namespace tpopt {

// {"name", "units": "mm", "kind": "ruled", "cutter_side": "positive" |
// "negative", "rails": [{degree, knots, control_points}, {...}]}.
Status ReadSurfaceJson(const std::string& path, RuledSurface* surface);

// {"name", "kinematics": "xyzac-trt", "rotary_pivot": [x, y, z], "y_offset",
// "z_offset", "tool_length", "axes": {"X": {min, max, max_velocity,
// max_acceleration, max_jerk}, ...}}: mm and degrees in the file, radians
// inside. Absent keys mean no limit (or 0 for the offsets).
Status ReadMachineJson(const std::string& path, Machine* machine);

}  // namespace tpopt

#endif  // TPOPT_MODEL_JSON_IO_H_
