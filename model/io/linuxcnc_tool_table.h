// LinuxCNC's tool table ([EMCIO] TOOL_TABLE of the INI): one tool a line,
// words of a letter and a number separated by blanks, a comment after ';':
//   T1 P1 D6.0 Z+12.5 ;end mill
// T is the tool number (required), P the pocket, X Y Z A B C U V W the
// offsets (Z: the tool length that G43 H applies), D the diameter, I J the
// lathe front and back angles, Q the lathe orientation; values in machine
// units (tpopt's INI reader takes mm machines only).
//
// LinuxCNC skips a line it cannot read with a message on its console and
// runs on; tpopt refuses it instead, naming the file, the line and the word,
// since a tool it could not size would be judged with another's cutter.
// Blank lines and lines that are only a comment are skipped. The old-style
// table (columns under a "POC FMS LEN DIAM" or "TOOLNO POCKET ..." header),
// which LinuxCNC still reads, is refused with a message that says so.
#ifndef TPOPT_MODEL_LINUXCNC_TOOL_TABLE_H_
#define TPOPT_MODEL_LINUXCNC_TOOL_TABLE_H_

#include <istream>
#include <map>
#include <string>

#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct LinuxCncTool {
  int number = 0;
  int pocket = 0;
  double diameter_mm = 0.0;
  double length_offset_mm = 0.0;  // Z
  std::string comment;
  int line = 0;  // 1-based line in the table
};

// Tools by number.
using LinuxCncToolTable = std::map<int, LinuxCncTool>;

// Reads the table; errors name the file, the line and the word. A tool
// number listed twice, a negative T or D, a word LinuxCNC's table lacks, a
// number that does not parse, and a line without T are refused.
Status ReadLinuxCncToolTable(const std::string& path, LinuxCncToolTable* table);
Status ParseLinuxCncToolTable(std::istream& in, const std::string& name,
                              LinuxCncToolTable* table);

// Sizes the tools a G-code program loads (ToolPath::tools, by number) from
// `table`: a tool of diameter D > 0 gets the cutter of radius D / 2 and
// `flute_length_mm`; D 0 leaves it unsized (the --cutter_radius or default
// cutter cuts its moves). path->cutter becomes the cutter of the first feed
// move's tool, if sized. Fails naming the program's line for a tool the
// table lacks, as LinuxCNC's M6 does.
Status SizeToolsFromTable(const LinuxCncToolTable& table, const std::string& table_name,
                          double flute_length_mm, ToolPath* path);

}  // namespace tpopt

#endif  // TPOPT_MODEL_LINUXCNC_TOOL_TABLE_H_
