// G-code in the LinuxCNC dialect, out and in.
//
// Styles (DESIGN.md):
//  - tcp:   X Y Z are the tool tip in the workpiece frame W, A C the rotary
//           joints; the controller's tool-centre-point mode does the rest
//           (LinuxCNC M428 in the xyzac-trt sample, Siemens TRAORI,
//           Heidenhain M128). The switch is a configurable preamble line.
//  - joint: X Y Z are machine joints from the inverse kinematics.
// Feeds: G94 with F in mm/min, or G93 inverse time with F = 1 / (minutes
// of the move) from the planned segment time (model/axis_metrics.h).
#ifndef TPOPT_MODEL_GCODE_IO_H_
#define TPOPT_MODEL_GCODE_IO_H_

#include <istream>
#include <string>
#include <vector>

#include "model/machine.h"
#include "model/status.h"
#include "model/tool_path.h"

namespace tpopt {

enum class GcodeStyle { kTcp, kJoint };

// The comment written on the G1 of a link (model/link_moves.h) and read back
// as one: a written program keeps its links whatever feed the scheduler gave
// them. Controllers ignore it like any comment.
constexpr char kLinkComment[] = "(link)";

struct GcodeOptions {
  GcodeStyle style = GcodeStyle::kTcp;
  bool inverse_time = false;  // G93 instead of G94
  // Lines written after the modal set-up and before the first move, e.g.
  // "M428" to switch LinuxCNC's xyzac-trt sample to TCP; and after the last.
  std::string preamble;
  std::string postamble;
  double default_feed_mm_per_min = 1000.0;
};

// The program text. Joints come from Machine::AssignJoints (one branch,
// unwrapped C); fails naming the pose when the path does not fit the
// machine. Coordinates carry 6 decimals (1 nm, 1e-6 deg): over the moves of a
// few hundredths of a mm a finishing program has, 4 decimals of C alone would
// add up to 0.16 deg/mm^2 of rounding to d2C/ds2.
Status FormatGcode(const ToolPath& path, const Machine& machine, const GcodeOptions& options,
                   std::string* program);

// Writes FormatGcode atomically.
Status WriteGcode(const std::string& file, const ToolPath& path, const Machine& machine,
                  const GcodeOptions& options);

// Reads a LinuxCNC program into poses: G0/G1 with modal words, ( ) and ;
// comments, G20/G21, G90/G91, G93/G94, M428/M429 noted (they switch the
// style to tcp/joint), other words warned once each. `style` is the style
// at the start. Arcs (G2/G3) and unknown G codes are errors naming the line.
Status ReadGcode(const std::string& file, const Machine& machine, GcodeStyle style,
                 ToolPath* path, std::vector<std::string>* warnings);
Status ReadGcodeStream(std::istream& in, const std::string& name, const Machine& machine,
                       GcodeStyle style, ToolPath* path, std::vector<std::string>* warnings);

}  // namespace tpopt

#endif  // TPOPT_MODEL_GCODE_IO_H_
