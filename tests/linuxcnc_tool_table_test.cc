#include "model/io/linuxcnc_tool_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "model/io/gcode_io.h"
#include "model/io/linuxcnc_ini.h"
#include "model/machine/machine.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::FileExists;
using testing::SourcePath;

constexpr char kTrtFolder[] =
    "/usr/share/doc/linuxcnc/examples/sample-configs/sim/axis/vismach/5axis/"
    "table-rotary-tilting/";

Status ParseText(const std::string& text, LinuxCncToolTable* table) {
  std::istringstream in(text);
  return ParseLinuxCncToolTable(in, "t.tbl", table);
}

// The xyzac-trt sim's own table, which its INI names: every tool, with
// the words LinuxCNC's tooledit writes.
TEST(LinuxCncToolTableTest, ReadsTheXyzacTrtSimTableItsIniNames) {
  const std::string ini = std::string(kTrtFolder) + "xyzac-trt.ini";
  if (!FileExists(ini)) GTEST_SKIP() << "LinuxCNC's sample configs are not installed";
  std::string path;
  ASSERT_TRUE(LinuxCncIniToolTable(ini, &path).ok());
  EXPECT_EQ(path, std::string(kTrtFolder) + "xyzac-trt.tbl");
  LinuxCncToolTable table;
  const Status s = ReadLinuxCncToolTable(path, &table);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(table.size(), 10u);
  EXPECT_EQ(table.at(1).diameter_mm, 1.0);
  EXPECT_EQ(table.at(1).comment, "end mill");
  EXPECT_EQ(table.at(2).diameter_mm, 8.0);
  EXPECT_EQ(table.at(2).length_offset_mm, 15.0);
  EXPECT_EQ(table.at(3).diameter_mm, 4.2);
  EXPECT_EQ(table.at(3).comment, "#7 tap drill");
  EXPECT_EQ(table.at(10).diameter_mm, 0.5);
  EXPECT_EQ(table.at(10).length_offset_mm, 0.0);
  EXPECT_EQ(table.at(10).line, 10);
}

// Every table under the sim configs: read, or refused for a reason the
// message names (old-style columns, a tool listed twice).
TEST(LinuxCncToolTableTest, EverySimTableIsReadOrRefusedByName) {
  const std::string sim = "/usr/share/doc/linuxcnc/examples/sample-configs/sim/";
  if (!FileExists(sim + "sim_mm.tbl")) GTEST_SKIP() << "LinuxCNC's sample configs are not installed";
  LinuxCncToolTable table;
  Status s = ReadLinuxCncToolTable(sim + "sim_mm.tbl", &table);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(table.size(), 24u);
  EXPECT_EQ(table.at(4).pocket, 2);  // T4 P2: numbers and pockets differ
  EXPECT_EQ(table.at(4).diameter_mm, 16.0);
  EXPECT_EQ(table.at(1).length_offset_mm, 0.511);
  s = ReadLinuxCncToolTable(sim + "axis/lathe.tbl", &table);  // I J Q, X offsets
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(table.at(10).diameter_mm, 0.0);
  s = ReadLinuxCncToolTable(sim + "axis/gantry/gantry_mm.tbl", &table);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("gantry_mm.tbl:1: 'TOOLNO POCKET"), std::string::npos)
      << s.message();
  EXPECT_NE(s.message().find("old-style tool table"), std::string::npos) << s.message();
  s = ReadLinuxCncToolTable(sim + "qtvcp_screens/woodpecker/tool.tbl", &table);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("tool.tbl:8: tool T6 is listed twice (line 7)"), std::string::npos)
      << s.message();
}

TEST(LinuxCncToolTableTest, BadLinesNameTheFileLineAndWord) {
  LinuxCncToolTable table;
  const std::string good = "; tools\n\nT1 P1 D6.0 Z+12.5 ;6 mm\n";
  ASSERT_TRUE(ParseText(good, &table).ok());
  ASSERT_EQ(table.size(), 1u);
  EXPECT_EQ(table.at(1).diameter_mm, 6.0);
  EXPECT_EQ(table.at(1).length_offset_mm, 12.5);
  EXPECT_EQ(table.at(1).comment, "6 mm");
  const struct {
    std::string text, message;
  } cases[] = {
      {good + "T2 P2 Dsix\n", "t.tbl:4: word 'Dsix': 'six' is not a number"},
      {good + "T2 P2 D6 Z1.5.2\n", "t.tbl:4: word 'Z1.5.2': '1.5.2' is not a number"},
      {good + "T2 P2 D\n", "t.tbl:4: word 'D': '' is not a number"},
      {good + "P2 D6\n", "t.tbl:4: 'P2 D6' names no tool (T word)"},
      {good + "T2 K6\n", "t.tbl:4: word 'K6' is not a tool table word"},
      {good + "T1.5 D6\n", "t.tbl:4: word 'T1.5': T takes a whole number"},
      {good + "T2 D-6\n", "t.tbl:4: word 'D-6': D must be >= 0"},
      {good + "T1 P3 D4\n", "t.tbl:4: tool T1 is listed twice (line 3)"},
      {good + "T2 D6 Znan\n", "t.tbl:4: word 'Znan': 'nan' is not a number"},
  };
  for (const auto& c : cases) {
    const Status s = ParseText(c.text, &table);
    ASSERT_FALSE(s.ok()) << c.text;
    EXPECT_NE(s.message().find(c.message), std::string::npos) << s.message();
  }
}

// T, M6 and M61 load tools in a G-code program; each move takes the tool
// loaded before it, and the table sizes them. A tool the table lacks is
// refused naming the program's line, as LinuxCNC's M6 is.
TEST(LinuxCncToolTableTest, GcodeToolsAreLoadedAndSizedFromTheTable) {
  Machine machine;
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(
      ReadGcode(SourcePath("tests/data/gcode/g53_tool_change.ngc"), machine, GcodeStyle::kTcp,
                &path, &warnings)
          .ok());
  ASSERT_EQ(path.tools.size(), 2u);
  EXPECT_EQ(path.tools[0].number, 1);
  EXPECT_EQ(path.tools[0].source_line, 6);
  EXPECT_EQ(path.tools[1].number, 2);
  EXPECT_EQ(path.tools[1].source_line, 40);
  for (const ToolPose& p : path.poses) {
    EXPECT_EQ(p.tool, p.source_line < 40 ? 0 : 1) << p.source_line;
  }
  LinuxCncToolTable table;
  ASSERT_TRUE(ParseText("T1 P1 D8 Z10\nT2 P2 D4 Z20\n", &table).ok());
  ASSERT_TRUE(SizeToolsFromTable(table, "t.tbl", 30.0, &path).ok());
  EXPECT_EQ(path.tools[0].cutter->radius_mm, 4.0);
  EXPECT_EQ(path.tools[1].cutter->radius_mm, 2.0);
  EXPECT_EQ(path.tools[1].cutter->flute_length_mm, 30.0);
  EXPECT_EQ(path.cutter->radius_mm, 4.0);
  ASSERT_TRUE(ParseText("T1 P1 D8\n", &table).ok());
  const Status s = SizeToolsFromTable(table, "t.tbl", 30.0, &path);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "line 40: tool T2 is not in the tool table t.tbl");
  // M61 Q3 sets the loaded tool without a change; T0 M6 empties the spindle.
  std::istringstream in(
      "G21 G90\nM61 Q3\nG0 X0 Y0 Z5 A0 C0\nG1 X1 F100\nT0 M6\nG0 X0 Y0 Z5 A0 C0\nG1 X2\n");
  ToolPath p2;
  ASSERT_TRUE(ReadGcodeStream(in, "m61.ngc", machine, GcodeStyle::kTcp, &p2, &warnings).ok());
  ASSERT_EQ(p2.tools.size(), 1u);
  EXPECT_EQ(p2.tools[0].number, 3);
  EXPECT_EQ(p2.poses.front().tool, 0);
  EXPECT_EQ(p2.poses.back().tool, -1);
}

// What G43 H means on xyzac-trt-kins wired as the sims are (tool-offset
// from motion.tooloffset.z): LinuxCNC sends p + L ez to a kinematics whose
// tool offset is L, and the joints it gets are those of the tip p with no
// offset, L higher in Z. So the tip's path in the table frame does not
// depend on L; only joint Z does. Checked on tpopt's copy of the inverse.
TEST(LinuxCncToolTableTest, ALengthOffsetOnlyRaisesJointZ) {
  KinematicParams with, without;
  without.rotary_pivot_mm = Eigen::Vector3d(10, -20, 30);
  without.y_offset_mm = 5;
  without.z_offset_mm = 20;
  with = without;
  const double lengths[] = {0.0, 15.0, 123.4};
  for (double length : lengths) {
    with.tool_length_mm = length;
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector3d p = Eigen::Vector3d::Random() * 100;
      const double a = 1.5 * std::sin(k), c = 3.0 * std::cos(3 * k);
      const Eigen::Vector3d joints =
          WorkpieceToJoints<double>(with, p + Eigen::Vector3d(0, 0, length), a, c);
      const Eigen::Vector3d tip_joints = WorkpieceToJoints<double>(without, p, a, c);
      EXPECT_NEAR((joints - tip_joints - Eigen::Vector3d(0, 0, length)).norm(), 0.0, 1e-9);
    }
  }
}

// G43 H takes the table's Z for the moves after it (G49 ends it), and the
// travel check raises joint Z by it: on the sim machine a 1000 mm tool does
// not fit, and the message says why.
TEST(LinuxCncToolTableTest, G43OffsetsAreTheTablesAndJudgeTheZTravel) {
  const std::string ini = std::string(kTrtFolder) + "xyzac-trt.ini";
  if (!FileExists(ini)) GTEST_SKIP() << "LinuxCNC's sample configs are not installed";
  Machine machine;
  ASSERT_TRUE(ReadLinuxCncIni(ini, &machine).ok());
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(ReadGcode(SourcePath("tests/data/gcode/g53_tool_change.ngc"), machine,
                        GcodeStyle::kTcp, &path, &warnings)
                  .ok());
  LinuxCncToolTable table;
  ASSERT_TRUE(ParseText("T1 P1 D8 Z10\nT2 P2 D4 Z1000\n", &table).ok());
  ASSERT_TRUE(SizeToolsFromTable(table, "t.tbl", 30.0, &path).ok());
  for (const ToolPose& p : path.poses) {
    EXPECT_EQ(p.length_offset_tool, p.source_line < 40 ? 1 : 2) << p.source_line;
    EXPECT_EQ(p.length_offset_mm, p.source_line < 40 ? 10.0 : 1000.0) << p.source_line;
  }
  std::vector<JointVector> joints;
  ASSERT_TRUE(machine.AssignJoints(path, &joints).ok());
  Status s = machine.CheckTravel(path, joints);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("(line 45): Z = "), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("with the tool length offset of 1000 mm"), std::string::npos)
      << s.message();
  for (ToolPose& p : path.poses) p.length_offset_mm = 0.0;
  EXPECT_TRUE(machine.CheckTravel(path, joints).ok());
  // H of a tool the table lacks: refused naming the line.
  ToolPath again;
  ASSERT_TRUE(ReadGcode(SourcePath("tests/data/gcode/g53_tool_change.ngc"), machine,
                        GcodeStyle::kTcp, &again, &warnings)
                  .ok());
  ASSERT_TRUE(ParseText("T1 P1 D8 Z10\nT2 P2 D4\n", &table).ok());
  for (ToolPose& p : again.poses) {
    if (p.length_offset_tool == 2) p.length_offset_tool = 7;
  }
  s = SizeToolsFromTable(table, "t.tbl", 30.0, &again);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find(": G43 H7: tool T7 is not in the tool table t.tbl"),
            std::string::npos)
      << s.message();
}

}  // namespace
}  // namespace tpopt
