// APT cutter-location files (and NX CLSF): the reader accepts what real
// CAM systems write and keeps the program record for record
// (ToolPath::program, model/path/program.h); the writers emit either that program
// with only its smoothed cutting moves replaced, or a plain 5-axis CL file
// that reads back to within 1e-6 mm.
//
// Statements: GOTO/x,y,z[,i,j,k] (i,j,k modal; +Z before the first), `$` at
// the end of a line continues the statement, `$$` starts a comment.
// TLDATA/MILL,d,r,l,... and CUTTER/d[,r,...] define a tool with its corner
// radius, LOAD/TOOL,n and LOADTL/n load one (a LOAD and a geometry record
// with no GOTO between are one tool; ToolPath::tools, ToolPose::tool).
// FEDRAT/[MMPM|IPM,]f is the modal feed; UNITS/MM|INCHES, and FEDRAT/IPM with
// no UNITS record (NX), set the units (inch is read into mm). RAPID makes the
// next GOTO a rapid. CIRCLE/xc,yc,zc,i,j,k,r[,...] turns the next GOTO into
// an arc counter-clockwise about (i,j,k), evaluated into points within
// 0.001 mm. NX's NURBS/ with KNOT/ (the knot vector) and CNTRL/x,y,z[,w]
// records is a clamped NURBS from the tool's position, evaluated likewise
// (degree = knots - control points - 1). tpopt's own span records
// (AptCurveSpan) are followed by their points as GOTOs. CYCLE/... up to
// CYCLE/OFF makes its GOTOs cycle positions (rapids). SPINDL, COOLNT,
// CUTCOM, INSERT, SELECT, CSYS, MSYS, PARTNO, MULTAX, TOOL PATH, PAINT and
// the like carry nothing tpopt needs; any other statement is passed through
// with one warning per distinct major word (its first word, or TOOL PATH).
// Words are case-insensitive; blanks, CRLF, and blank or comment lines
// inside a `$` continuation are tolerated. Numbers are plain decimals.
//
// Kept as written (ProgramBlock::replaceable false, the pose held): rapids,
// cycle positions, arcs and curves and the moves on both sides of them, the
// points of tpopt's spans, and the moves on both sides of a record that can
// matter to the machine, which breaks the cutting run (any but FEDRAT,
// PAINT, MULTAX, TOOL PATH, PARTNO, UNITS, PPRINT, MACHIN, END-OF-PATH,
// FINI, END, RAPID and comment lines).
#ifndef TPOPT_MODEL_APT_IO_H_
#define TPOPT_MODEL_APT_IO_H_

#include <Eigen/Core>
#include <array>
#include <istream>
#include <string>
#include <vector>

#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

// Reads `path` as a stream (memory grows with the poses, not the file).
// Errors name the file, the line and the value: unreadable numbers, NaN,
// Inf or |v| > 1e6, a GOTO with other than 3 or 6 numbers, a zero tool axis,
// UNITS other than MM or INCHES (or INCHES after a GOTO read in mm), a feed
// unit that contradicts the units or is per revolution, a CIRCLE whose ends
// are off its circle or that no GOTO follows, NURBS records that make no
// curve or start away from the tool, a `$` continuation cut off by the end
// of file, or no GOTO at all. Non-unit axes are normalised.
Status ReadApt(const std::string& path, ToolPath* tool_path, std::vector<std::string>* warnings);

// The same from an open stream; `name` stands for the file in messages.
Status ReadAptStream(std::istream& in, const std::string& name, ToolPath* tool_path,
                     std::vector<std::string>* warnings);

// A cubic span of the tip path, mm in W, for controllers with spline
// interpolation. It is written right after the GOTO of pose `after_pose`
// (its start point, bezier[0]) as
//   NURBS/3,4,0,0,0,0,1,1,1,1,$
//   x0,y0,z0,1,$  ...  x3,y3,z3,1
// (degree, number of control points, clamped knots, then each control
// point with weight 1): one Bezier span, non-rational. The GOTOs that
// follow, up to the next NURBS or RAPID, are points of that span, densely
// resampled for controllers without spline support, its end point last.
struct AptCurveSpan {
  size_t after_pose = 0;
  std::array<Eigen::Vector3d, 4> bezier;
};

// APT text: a `$$` header with the title (control characters blanked),
// UNITS/MM, MULTAX/ON, TLDATA/MILL,d,0,l when the cutter is known (taper is
// not written) or, for a path with ToolPath::tools, TLDATA/MILL,d,r,l and
// LOAD/TOOL,n before the first move of each tool, FEDRAT/MMPM (10 significant digits) when the feed changes,
// RAPID before rapids, GOTO with 6 decimals of mm and 9 of the axis,
// END-OF-PATH and FINI. Read back, tips agree within 1e-6 mm and axes
// within 1e-9.
// `spans` (sorted by after_pose) are written as NURBS records.
std::string FormatApt(const ToolPath& tool_path, const std::vector<AptCurveSpan>& spans = {});

// Writes FormatApt atomically (model/io/atomic_file.h). Refuses, writing
// nothing, a path ReadApt would reject: no poses, or a pose (named by its
// 0-based index) with a non-finite value, a coordinate beyond 1e6 mm or a
// zero axis; or a span after no pose, out of order, or not finite.
Status WriteApt(const std::string& path, const ToolPath& tool_path,
                const std::vector<AptCurveSpan>& spans = {});

// The APT program `input` was read from (input.program), written back with
// `output`, a path smoothed from `input`, laid into it (SpliceProgram): every
// record and comment line as it was, in order, and each replaced cutting
// move as GOTO/x,y,z,i,j,k in its record's units (6 decimals of mm or 7 of
// inch, 9 of the axis), after FEDRAT/MMPM|IPM when its feed differs from the
// one in effect; the source's feed is restored before the next record
// written as it was. `spans` go after the GOTO of their pose, as in
// FormatApt. A path that was not smoothed comes back byte for byte. Fails
// as SpliceProgram does, naming the line.
Status FormatAptProgram(const ToolPath& input, const ToolPath& output,
                        const std::vector<AptCurveSpan>& spans, std::string* text);

// Writes FormatAptProgram atomically, after the checks of WriteApt; errors
// name `path`.
Status WriteAptProgram(const std::string& path, const ToolPath& input, const ToolPath& output,
                       const std::vector<AptCurveSpan>& spans = {});

}  // namespace tpopt

#endif  // TPOPT_MODEL_APT_IO_H_
