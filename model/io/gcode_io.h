// G-code in the LinuxCNC dialect, out and in.
//
// Styles (docs/ARCHITECTURE.md, "Interpolation models"):
//  - tcp:   X Y Z are the tool tip in the workpiece frame W, A C the rotary
//           joints; the controller's tool-centre-point mode does the rest
//           (LinuxCNC M428 in the xyzac-trt sample, Siemens TRAORI,
//           Heidenhain M128). The switch is a configurable preamble line.
//  - joint: X Y Z are machine joints from the inverse kinematics.
// Feeds: G94 with F in mm/min, or G93 inverse time with F = 1 / (minutes
// of the move) from the planned segment time (model/machine/axis_metrics.h).
#ifndef TPOPT_MODEL_GCODE_IO_H_
#define TPOPT_MODEL_GCODE_IO_H_

#include <istream>
#include <string>
#include <vector>

#include "model/machine/machine.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

enum class GcodeStyle { kTcp, kJoint };

// The comment written on the G1 of a link (model/path/link_moves.h) and read back
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
  // Feed of the moves whose pose has none, and the feed the planned segment
  // times of G93 assume there, mm/min. Finite and > 0.
  double default_feed_mm_per_min = 1000.0;

  // False, with `why` naming the field and the value, for a bad value.
  bool IsValid(std::string* why) const;
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

// Writes `output`, a path smoothed from `input` (read by ReadGcode, so
// output.program is its G-code program), as that program block for block
// (model/path/program.h): every block as it was, save the replaced cutting moves
// of the smoothed runs, written "G1 X Y Z A C F" in their blocks' units,
// style (tcp/joint) and feed mode (G94, or G93 with F from the planned
// segment time). Where written feeds left the controller's F other than
// the source's, an F line restores it before the next source block. The
// options' style, preamble, postamble and inverse_time do not apply: the
// program has its own. Fails naming the line where `output` does not fit
// the program, or naming the pose where it does not fit the machine.
Status FormatGcodeProgram(const ToolPath& input, const ToolPath& output, const Machine& machine,
                          const GcodeOptions& options, std::string* text);
Status WriteGcodeProgram(const std::string& file, const ToolPath& input, const ToolPath& output,
                         const Machine& machine, const GcodeOptions& options);

// Reads a LinuxCNC program into poses and path->program, its every line a
// block (model/path/program.h). A move becomes a pose once all five axes X Y Z
// A C are known; moves before that, G53 moves, canned cycles and probing
// are kept as blocks without poses, and the axes they move are unknown
// again, as after offset changes (G10, G52, G92, G5x), tool changes (M6) and
// G28/G30 (Z alone after G43/G49). G2/G3 arcs are poses at their ends, kept
// as programmed. ( ) and ; comments, G20/G21, G90/G91, G93/G94/G95,
// M428/M429 (switching the style to tcp/joint), parameters and expressions
// (model/io/gcode_expression.h) are read; nothing after M2/M30 is. `style` is
// the style at the start. Refused, naming the line and the construct:
// words for axes an A/C machine lacks (B U V W), o-words, block delete,
// unknown G codes, parameters read before the program sets them where
// LinuxCNC would read machine state. Tools: T selects, M6 loads (T0 empties
// the spindle) and M61 Q sets the loaded tool; each load is a ToolRecord
// (unsized: the tool table sizes it, model/io/linuxcnc_tool_table.h) and each
// pose takes the tool loaded before it, with its tool length offset (G43
// [H], G43.1 Z, G43.2, G49; ToolPose::length_offset_*).
Status ReadGcode(const std::string& file, const Machine& machine, GcodeStyle style,
                 ToolPath* path, std::vector<std::string>* warnings);
Status ReadGcodeStream(std::istream& in, const std::string& name, const Machine& machine,
                       GcodeStyle style, ToolPath* path, std::vector<std::string>* warnings);

}  // namespace tpopt

#endif  // TPOPT_MODEL_GCODE_IO_H_
