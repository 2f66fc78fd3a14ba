#include "model/io/apt_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tests/test_util.h"

namespace tpopt {
namespace {

Status Parse(const std::string& text, ToolPath* path, std::vector<std::string>* warnings) {
  std::istringstream in(text);
  return ReadAptStream(in, "p.cls", path, warnings);
}

std::string ErrorOf(const std::string& text) {
  ToolPath path;
  std::vector<std::string> warnings;
  const Status s = Parse(text, &path, &warnings);
  return s.ok() ? "" : s.message();
}

TEST(AptIoTest, ReadsWhatRealCamSystemsWrite) {
  const std::string text =
      "$$ header comment\r\n"
      "TOOL PATH/FLANK,TOOL,EM8\n"
      "TLDATA/MILL,8.0,0.0,30.0,0.0,0.0\n"
      "UNITS/MM\n"
      "MULTAX/ON\n"
      "PAINT/COLOR,186\n"
      "fedrat/mmpm, 1200\n"
      "GOTO/1,2,3,0,0,1 $$ first\n"
      "GOTO/1.5,2,3\n"
      "RAPID\n"
      "GOTO/10,20,30,$\n"
      "  0.6,0,0.8\n"
      "GOTO/11,20,30\n"
      "FEDRAT/500,MMPM\n"
      "SPINDL/RPM,8000\n"
      "CUTCOM/LEFT\n"
      "CUTCOM/OFF\n"
      "INSERT G05.1 Q1\n"
      "GOTO/12,20,30\n"
      "INSERT M08\n"
      "END-OF-PATH\n"
      "FINI\n";
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(Parse(text, &path, &warnings).ok());
  ASSERT_EQ(path.poses.size(), 5u);
  ASSERT_TRUE(path.cutter.has_value());
  EXPECT_EQ(path.cutter->radius_mm, 4.0);
  EXPECT_EQ(path.cutter->flute_length_mm, 30.0);
  // Modal axis, modal feed, one-shot rapid, continuation, source lines.
  EXPECT_EQ(path.poses[1].a_w, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(path.poses[1].feed_mm_per_min, 1200);
  EXPECT_FALSE(path.poses[1].rapid);
  EXPECT_TRUE(path.poses[2].rapid);
  EXPECT_EQ(path.poses[2].source_line, 11);
  EXPECT_LT((path.poses[2].a_w - Eigen::Vector3d(0.6, 0, 0.8)).norm(), 1e-15);
  EXPECT_FALSE(path.poses[3].rapid);
  EXPECT_EQ(path.poses[3].a_w, path.poses[2].a_w);
  EXPECT_EQ(path.poses[4].feed_mm_per_min, 500);
  // CUTCOM and INSERT are known records, passed through in silence.
  EXPECT_TRUE(warnings.empty()) << warnings[0];
}

TEST(AptIoTest, UnknownStatementsWarnOncePerWordAndArePassedThrough) {
  const std::string text = "GOTO/0,0,0\nFROB/1\nGOTO/1,0,0\nFROB/2\nWIBBLE 3\nGOTO/2,0,0\n";
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(Parse(text, &path, &warnings).ok());
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("p.cls:2: statement 'FROB' is not understood; passed through"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[1].find("p.cls:5: statement 'WIBBLE'"), std::string::npos) << warnings[1];
  ASSERT_NE(path.program, nullptr);
  ASSERT_EQ(path.program->blocks.size(), 6u);
  EXPECT_EQ(path.program->blocks[3].text, "FROB/2");
  EXPECT_EQ(path.program->blocks[3].pose, -1);
}

TEST(AptIoTest, NormalisesAxesAndAcceptsCutter) {
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(Parse("CUTTER/10\nGOTO/0,0,0,0,0,2\n", &path, &warnings).ok());
  EXPECT_EQ(path.cutter->radius_mm, 5.0);
  EXPECT_EQ(path.poses[0].a_w, Eigen::Vector3d(0, 0, 1));
}

TEST(AptIoTest, BadInputNamesLineAndValue) {
  EXPECT_NE(
      ErrorOf("GOTO/1,2,3\nGOTO/1,2,3,0,0\n").find("p.cls:2: GOTO needs 3 or 6 numbers, got 5"),
      std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/1,2,3\nGOTO/1,2,3,1\n").find("got 4"), std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/1,abc,3\n").find("p.cls:1: GOTO argument 2 'abc' is not a number"),
            std::string::npos);
  EXPECT_NE(ErrorOf("\nGOTO/1,nan,3\n").find("p.cls:2: GOTO argument 2 'nan'"), std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/1,inf,3\n").find("p.cls:1: GOTO argument 2 'inf' is not a number"),
            std::string::npos);
  // strtod would read hex; no CAM system writes it, so it is garbage here.
  EXPECT_NE(ErrorOf("GOTO/0x10,2,3\n").find("p.cls:1: GOTO argument 1 '0x10' is not a number"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/1,2,3\nGOTO/1,2,3,1,2,3,4\n")
                .find("p.cls:2: GOTO needs 3 or 6 "
                      "numbers, got 7"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/1,2,3\nGOTO/1,2,3,1e-10,0,0\n").find("p.cls:2: zero-length tool axis"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/1e308,0,3\n").find("'1e308' is out of range"), std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/1,2,3,0,0,0\n").find("p.cls:1: zero-length tool axis"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/1,2,3\nGOTO/4,5,$\n").find("p.cls:2: statement continued"),
            std::string::npos);
  EXPECT_NE(ErrorOf("UNITS/MM\nFINI\n").find("no GOTO"), std::string::npos);
  EXPECT_NE(ErrorOf("UNITS/FEET\nGOTO/1,2,3\n").find("p.cls:1: UNITS/FEET is not supported"),
            std::string::npos);
  EXPECT_NE(ErrorOf("TLDATA/MILL,-8,0,20\nGOTO/1,2,3\n").find("p.cls:1: cutter radius -4"),
            std::string::npos);
  EXPECT_NE(ErrorOf("UNITS/MM\nFEDRAT/IPM,20\nGOTO/1,2,3\n")
                .find("p.cls:2: FEDRAT/IPM in a program whose units are mm"),
            std::string::npos);
  EXPECT_NE(ErrorOf("FEDRAT/IPR,0.1\nGOTO/1,2,3\n").find("p.cls:1: FEDRAT unit IPR"),
            std::string::npos);
  EXPECT_NE(ErrorOf("").find("no GOTO"), std::string::npos);
  // In range as inch, not as mm.
  const std::string inch = ErrorOf("UNITS/INCHES\nGOTO/0,0,0\nGOTO/100000,0,0\n");
  EXPECT_EQ(inch.find("p.cls:3: a move to (2.54e+06"), 0u) << inch;
  EXPECT_NE(inch.find("mm is out of range (|v| <= 1e6 mm)"), std::string::npos) << inch;
  // So with a feed and a tool: tpopt writes them in mm, and must read them back.
  EXPECT_NE(ErrorOf("UNITS/INCHES\nFEDRAT/102221\nGOTO/0,0,0\n")
                .find("p.cls:3: the feed 2596413.4"),
            std::string::npos);
  EXPECT_NE(ErrorOf("UNITS/INCHES\nTLDATA/MILL,40000,0,10\nGOTO/0,0,0\n")
                .find("p.cls:2: the tool's diameter 1016000.0"),
            std::string::npos);
  EXPECT_EQ(ErrorOf("UNITS/INCHES\nFEDRAT/39000\nTLDATA/MILL,39000,0,39000\nGOTO/0,0,0\n"), "");
}

TEST(AptIoTest, ContinuationSkipsBlankAndCommentLines) {
  // Some posts put a comment between the lines of a continued GOTO; the pose
  // still belongs to the GOTO's own line.
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(
      Parse("GOTO/0,0,0\n\nGOTO/1,2,$\n$$ note\n\n  3,0,$\r\n1,0\n", &path, &warnings).ok());
  ASSERT_EQ(path.poses.size(), 2u);
  EXPECT_EQ(path.poses[1].p_w_tip, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(path.poses[1].a_w, Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(path.poses[1].source_line, 3);
  EXPECT_TRUE(warnings.empty());
}

TEST(AptIoTest, SilentWordsWithFreeTextGiveNoWarning) {
  // PARTNO and TOOL PATH carry free text, slashes and commas included.
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(Parse("PARTNO blade 1/2, rev B\ntool   "
                    "path/FLANK,1\nLOADTL/1\nSPINDL/8000\n"
                    "COOLNT/ON\nMULTAX\nGOTO/1,2,3\nFINI\n",
                    &path, &warnings)
                  .ok());
  EXPECT_TRUE(warnings.empty()) << warnings[0];
  EXPECT_EQ(path.poses[0].source_line, 7);
}

TEST(AptIoTest, BadFilesNameThePathAndLine) {
  testing::TempDir dir;
  struct Case {
    const char* name;
    const char* text;
    const char* expected;  // after the full path
  };
  const Case cases[] = {
      {"axis.cls", "GOTO/1,2,3\nGOTO/1,2,3,0,0,0\n", ":2: zero-length tool axis (0, 0, 0)"},
      {"four.cls", "$$ c\nGOTO/1,2,3,4\n", ":2: GOTO needs 3 or 6 numbers, got 4"},
      {"empty.cls", "UNITS/MM\r\nFINI\r\n", ": no GOTO"},
      {"cont.cls", "GOTO/1,2,3\nGOTO/4,5,$\n$$ end\n", ":2: statement continued"},
      {"inch.cls", "GOTO/1,2,3\nUNITS/INCHES\n", ":2: UNITS/INCHES after the first GOTO"},
      {"big.cls", "GOTO/1,2,3\nGOTO/1,2000000,3\n",
       ":2: GOTO argument 2 '2000000' is out of range"},
  };
  for (const Case& c : cases) {
    const std::string file = dir.File(c.name);
    std::ofstream(file) << c.text;
    ToolPath path;
    std::vector<std::string> warnings;
    const Status s = ReadApt(file, &path, &warnings);
    ASSERT_FALSE(s.ok()) << c.name;
    EXPECT_EQ(s.message().rfind(file + c.expected, 0), 0u) << s.message();
    EXPECT_TRUE(path.poses.empty()) << c.name;  // nothing half read
  }
  ToolPath path;
  const Status s = ReadApt(dir.File("missing.cls"), &path, nullptr);
  EXPECT_EQ(s.message(), dir.File("missing.cls") + ": cannot open file");
}

TEST(AptIoTest, FormatKeepsTheTitleInItsCommentAndFeedsExact) {
  ToolPath path;
  path.title = "smooth of evil\nGOTO/9,9,9\r";
  ToolPose pose;
  pose.feed_mm_per_min = 1234.56789;
  path.poses.push_back(pose);
  pose.feed_mm_per_min = 1234.56789;  // unchanged: no second FEDRAT
  pose.p_w_tip.x() = 1;
  path.poses.push_back(pose);
  const std::string text = FormatApt(path);
  EXPECT_EQ(text.rfind("$$ smooth of evil GOTO/9,9,9 \n", 0), 0u) << text;
  EXPECT_NE(text.find("FEDRAT/MMPM,1234.56789\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("FEDRAT", text.find("FEDRAT") + 1), std::string::npos) << text;
  ToolPath back;
  ASSERT_TRUE(Parse(text, &back, nullptr).ok());
  ASSERT_EQ(back.poses.size(), 2u);
  EXPECT_EQ(back.poses[0].p_w_tip, Eigen::Vector3d::Zero());
  EXPECT_EQ(back.poses[1].feed_mm_per_min, 1234.56789);
}

TEST(AptIoTest, WriteRefusesWhatCannotBeReadBack) {
  testing::TempDir dir;
  ToolPath path;
  EXPECT_NE(WriteApt(dir.File("e.cls"), path).message().find("e.cls: no poses"), std::string::npos);
  path.poses.resize(3);
  path.poses[2].p_w_tip.y() = std::nan("");
  Status s = WriteApt(dir.File("n.cls"), path);
  EXPECT_NE(s.message().find("n.cls: pose 2 cannot be written"), std::string::npos) << s.message();
  path.poses[2].p_w_tip.y() = 0;
  path.poses[1].a_w.setZero();
  s = WriteApt(dir.File("z.cls"), path);
  EXPECT_NE(s.message().find("z.cls: pose 1"), std::string::npos) << s.message();
  EXPECT_FALSE(testing::FileExists(dir.File("e.cls")));
  EXPECT_FALSE(testing::FileExists(dir.File("n.cls")));
  EXPECT_FALSE(testing::FileExists(dir.File("z.cls")));
}

TEST(AptIoTest, CurveSpansAreNurbsRecordsAfterTheirStartAndReadBackInSilence) {
  ToolPath path;
  for (int i = 0; i < 4; ++i) {
    ToolPose pose;
    pose.p_w_tip = {double(i), 0, 0};
    path.poses.push_back(pose);
  }
  AptCurveSpan span;
  span.after_pose = 1;
  span.bezier = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1.25, 0.5, 0),
                 Eigen::Vector3d(1.75, -0.5, 0), Eigen::Vector3d(2, 0, 1e-10)};
  const std::string text = FormatApt(path, {span});
  const std::string record =
      "GOTO/1.000000,0.000000,0.000000,0.000000000,0.000000000,1.000000000\n"
      "NURBS/3,4,0,0,0,0,1,1,1,1,$\n1.000000000,0.000000000,0.000000000,1,$\n"
      "1.250000000,0.500000000,0.000000000,1,$\n1.750000000,-0.500000000,0."
      "000000000,1,$\n"
      "2.000000000,0.000000000,0.000000000,1\nGOTO/2.000000";
  EXPECT_NE(text.find(record), std::string::npos) << text;
  ToolPath back;
  std::vector<std::string> warnings;
  ASSERT_TRUE(Parse(text, &back, &warnings).ok());
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(back.poses.size(), 4u);

  testing::TempDir dir;
  span.after_pose = 4;  // past the last pose
  Status s = WriteApt(dir.File("s.cls"), path, {span});
  EXPECT_NE(s.message().find("curve span 0 after pose 4"), std::string::npos) << s.message();
  span.after_pose = 2;
  span.bezier[2].x() = INFINITY;
  EXPECT_FALSE(WriteApt(dir.File("s.cls"), path, {span}).ok());
  EXPECT_FALSE(testing::FileExists(dir.File("s.cls")));
}

TEST(AptIoTest, RoundTripsThroughAFile) {
  ToolPath path;
  path.title = "round trip";
  path.cutter = Cutter{3.0, 25.0, 0.0};
  for (int i = 0; i < 50; ++i) {
    ToolPose p;
    p.p_w_tip = Eigen::Vector3d(0.1234567 * i, -3.3333333 * i, 100 + std::sin(i));
    p.a_w = Eigen::Vector3d(std::sin(0.1 * i), 0.2, 1).normalized();
    p.feed_mm_per_min = i < 25 ? 800 : 1500;
    p.rapid = i == 30;
    path.poses.push_back(p);
  }
  char pattern[] = "/tmp/tpopt_apt_XXXXXX";
  const std::string dir = mkdtemp(pattern);
  const std::string file = dir + "/rt.cls";
  ASSERT_TRUE(WriteApt(file, path).ok());
  ToolPath back;
  std::vector<std::string> warnings;
  ASSERT_TRUE(ReadApt(file, &back, &warnings).ok());
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(back.poses.size(), path.poses.size());
  for (size_t i = 0; i < path.poses.size(); ++i) {
    EXPECT_LT((back.poses[i].p_w_tip - path.poses[i].p_w_tip).norm(), 1e-6) << i;
    EXPECT_LT((back.poses[i].a_w - path.poses[i].a_w).norm(), 1e-9) << i;
    EXPECT_EQ(back.poses[i].rapid, path.poses[i].rapid) << i;
    if (!path.poses[i].rapid) {
      EXPECT_EQ(back.poses[i].feed_mm_per_min, path.poses[i].feed_mm_per_min) << i;
    }
  }
  EXPECT_EQ(back.cutter->radius_mm, 3.0);
  EXPECT_EQ(back.cutter->flute_length_mm, 25.0);
  std::system(("rm -rf " + dir).c_str());
}

// The corpus under tests/programs: small programs written from the
// formats' documentation (NX CLSF: inch without UNITS, MSYS, two tools,
// CIRCLE, NURBS/KNOT/CNTRL; APT: CYCLE, CUTCOM, INSERT, SELECT, CSYS).
const char* const kCorpus[] = {"nx_inch_tools.cls", "apt_cycle_cutcom.apt"};

std::string CorpusFile(const std::string& name) {
  return std::string(TPOPT_SOURCE_DIR) + "/tests/programs/" + name;
}

ToolPath ReadCorpus(const std::string& name) {
  ToolPath path;
  std::vector<std::string> warnings;
  const Status s = ReadApt(CorpusFile(name), &path, &warnings);
  EXPECT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(warnings.empty()) << name << ": " << warnings[0];
  return path;
}

TEST(AptProgramTest, EveryCorpusProgramComesBackByteForByteWhenNotSmoothed) {
  for (const char* name : kCorpus) {
    const ToolPath path = ReadCorpus(name);
    std::string text;
    const Status s = FormatAptProgram(path, path, {}, &text);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(text, testing::ReadFileText(CorpusFile(name))) << name;
  }
}

TEST(AptProgramTest, CrlfAndNoFinalNewlineComeBackAsWritten) {
  const std::string text = "$$ c\r\nGOTO/1,2,3\r\nGOTO/1,$\r\n 2,4\r\nFINI";
  ToolPath path;
  ASSERT_TRUE(Parse(text, &path, nullptr).ok());
  std::string back;
  ASSERT_TRUE(FormatAptProgram(path, path, {}, &back).ok());
  EXPECT_EQ(back, text);
}

TEST(AptProgramTest, InchProgramIsReadInMmWithItsToolsAndCornerRadii) {
  const ToolPath path = ReadCorpus("nx_inch_tools.cls");
  const Program& program = *path.program;
  // FEDRAT/IPM and no UNITS: the whole program is inch, the rapids before
  // the first FEDRAT included.
  EXPECT_EQ(path.poses[0].p_w_tip, Eigen::Vector3d(25.4, 0.0, 50.8));
  for (const ProgramBlock& b : program.blocks) EXPECT_EQ(b.mm_per_unit, 25.4) << b.line;
  ASSERT_EQ(path.tools.size(), 2u);
  EXPECT_EQ(path.tools[0].number, 1);
  EXPECT_DOUBLE_EQ(path.tools[0].cutter->radius_mm, 6.35);
  EXPECT_DOUBLE_EQ(path.tools[0].corner_radius_mm, 0.762);
  EXPECT_DOUBLE_EQ(path.tools[0].cutter->flute_length_mm, 76.2);
  EXPECT_EQ(path.tools[1].number, 2);
  EXPECT_DOUBLE_EQ(path.tools[1].cutter->radius_mm, 3.175);
  EXPECT_DOUBLE_EQ(path.tools[1].corner_radius_mm, 1.5875);
  EXPECT_DOUBLE_EQ(path.cutter->radius_mm, 6.35);
  // Each move has the tool loaded before it; feeds in mm/min.
  for (const ToolPose& p : path.poses) {
    EXPECT_EQ(p.tool, p.source_line < 48 ? 0 : 1) << p.source_line;
  }
  EXPECT_DOUBLE_EQ(path.poses.back().feed_mm_per_min, 15 * 25.4);
}

TEST(AptProgramTest, ToolsPairLoadAndGeometryInEitherOrderAndReloadKeepsGeometry) {
  ToolPath path;
  ASSERT_TRUE(Parse("LOAD/TOOL,7\nTLDATA/MILL,10,1,40\nGOTO/0,0,0\nCUTTER/4\nLOADTL/8\n"
                    "GOTO/1,0,0\nLOAD/TOOL,7\nGOTO/2,0,0\n",
                    &path, nullptr)
                  .ok());
  ASSERT_EQ(path.tools.size(), 3u);
  EXPECT_EQ(path.tools[0].number, 7);
  EXPECT_EQ(path.tools[0].cutter->radius_mm, 5.0);
  EXPECT_EQ(path.tools[0].cutter->flute_length_mm, 40.0);
  EXPECT_EQ(path.tools[0].corner_radius_mm, 1.0);
  EXPECT_EQ(path.tools[1].number, 8);
  EXPECT_EQ(path.tools[1].cutter->radius_mm, 2.0);
  EXPECT_EQ(path.tools[2].number, 7);
  EXPECT_EQ(path.tools[2].cutter->radius_mm, 5.0);
  EXPECT_EQ(path.tools[2].corner_radius_mm, 1.0);
  EXPECT_EQ(path.poses[0].tool, 0);
  EXPECT_EQ(path.poses[1].tool, 1);
  EXPECT_EQ(path.poses[2].tool, 2);
  EXPECT_NE(ErrorOf("TLDATA/MILL,10,6,40\nGOTO/0,0,0\n").find("p.cls:1: TLDATA corner radius 6"),
            std::string::npos);
}

TEST(AptIoTest, PlainOutputWritesEachToolWithItsCornerRadius) {
  // The programless writer (a path read from G-code, or made here) with
  // the tools of the NX corpus: each tool before its first move, read back
  // with its own diameter, corner radius and number.
  const ToolPath path = ReadCorpus("nx_inch_tools.cls");
  ToolPath plain = path;
  plain.program = nullptr;
  const std::string text = FormatApt(plain);
  EXPECT_NE(text.find("TLDATA/MILL,12.700000,0.762000,76.200000\nLOAD/TOOL,1\n"),
            std::string::npos);
  EXPECT_NE(text.find("TLDATA/MILL,6.350000,1.587500,50.800000\nLOAD/TOOL,2\n"), std::string::npos);
  ToolPath back;
  ASSERT_TRUE(Parse(text, &back, nullptr).ok());
  ASSERT_EQ(back.tools.size(), 2u);
  ASSERT_EQ(back.poses.size(), path.poses.size());
  for (size_t i = 0; i < path.poses.size(); ++i) EXPECT_EQ(back.poses[i].tool, path.poses[i].tool);
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(back.tools[k].number, path.tools[k].number);
    EXPECT_NEAR(back.tools[k].corner_radius_mm, path.tools[k].corner_radius_mm, 1e-6);
    EXPECT_NEAR(back.tools[k].cutter->radius_mm, path.tools[k].cutter->radius_mm, 1e-6);
  }
}

TEST(AptProgramTest, CircleAndNurbsBecomeHeldPointsOnTheCurve) {
  const ToolPath path = ReadCorpus("nx_inch_tools.cls");
  // CIRCLE (line 20) about the origin, radius 1 in, counter-clockwise from
  // (1,0) to (0,1); the NURBS (lines 23-27) the next quarter to (-1,0).
  int arc_points = 0, curve_points = 0;
  double worst_sag = 0.0;
  for (size_t i = 1; i < path.poses.size(); ++i) {
    const ToolPose& p = path.poses[i];
    const bool on_arc = p.source_line == 20 || p.source_line == 21;
    const bool on_curve = p.source_line == 23 || p.source_line == 27;
    if (!on_arc && !on_curve) continue;
    (on_arc ? arc_points : curve_points)++;
    EXPECT_TRUE(p.held) << i;
    // 1e-4 mm: the written weight 0.7071068 is rounded.
    EXPECT_NEAR(p.p_w_tip.norm(), 25.4, on_arc ? 1e-9 : 1e-4) << i;
    EXPECT_EQ(p.p_w_tip.z(), 0.0);
    EXPECT_GE(p.p_w_tip.y(), -1e-9) << i;  // the upper half, turning +Z
    EXPECT_LE(p.p_w_tip.x(), on_arc ? 25.4 : 1e-9) << i;
    // The chord to the point before sags at most 0.001 mm below the circle.
    const double half =
        0.5 * std::acos(std::clamp(
                  p.p_w_tip.normalized().dot(path.poses[i - 1].p_w_tip.normalized()), -1.0, 1.0));
    worst_sag = std::max(worst_sag, 25.4 * (1 - std::cos(half)));
  }
  // Quarter of r = 25.4 mm at 0.001 mm: 2 acos(1 - 0.001/25.4) = 0.017746
  // rad a step, ceil(1.5708/0.017746) = 89 chords each.
  EXPECT_EQ(arc_points, 89);
  EXPECT_GE(curve_points, 89);
  EXPECT_LE(worst_sag, 0.001 + 1e-6);
  // The moves on both sides of each curve stay as programmed; FEDRAT and
  // PAINT do not break a run, so the moves next to them may be replaced.
  int replaceable = 0;
  for (const ProgramBlock& b : path.program->blocks) replaceable += b.replaceable;
  EXPECT_EQ(replaceable, 11 + 12);
  const Program& program = *path.program;
  for (const ProgramBlock& b : program.blocks) {
    if (b.line == 18 || b.line == 21 || b.line == 27) {
      EXPECT_FALSE(b.replaceable) << b.line;
      ASSERT_GE(b.pose, 0) << b.line;
      EXPECT_TRUE(path.poses[b.pose].held) << b.line;
    }
  }
}

TEST(AptProgramTest, CycleRapidAndRecordsAreKeptAndBreakRuns) {
  const ToolPath path = ReadCorpus("apt_cycle_cutcom.apt");
  const Program& program = *path.program;
  ASSERT_EQ(program.blocks.size(), 58u);
  int replaceable = 0;
  for (const ProgramBlock& b : program.blocks) {
    const bool is_goto = b.text.rfind("GOTO", 0) == 0;
    EXPECT_EQ(b.pose >= 0, is_goto) << b.line;
    if (b.replaceable) ++replaceable;
    // Cycle positions (lines 15, 16) are rapids, kept.
    if (b.line == 15 || b.line == 16) {
      EXPECT_TRUE(path.poses[b.pose].rapid);
      EXPECT_FALSE(b.replaceable);
    }
  }
  // Two runs (14 and 10 GOTOs), each held at its first and last move (next
  // to CUTCOM/LEFT, CUTCOM/OFF, the tool change and COOLNT/OFF): 12 + 8
  // cutting moves may be replaced.
  EXPECT_EQ(replaceable, 12 + 8);
  ASSERT_EQ(path.tools.size(), 2u);
  EXPECT_EQ(path.tools[0].number, 3);
  EXPECT_EQ(path.tools[0].cutter->radius_mm, 5.0);
  EXPECT_EQ(path.tools[0].corner_radius_mm, 2.0);
  EXPECT_EQ(path.tools[1].number, 5);
  EXPECT_EQ(path.tools[1].corner_radius_mm, 0.5);
}

// What a smoother does to a program's path, independent of any method:
// each replaceable move's pose is moved, and a new pose is put before it.
ToolPath SimulatedSmoothing(const ToolPath& in) {
  ToolPath out = WithoutPoses(in);
  for (const ToolPose& p : in.poses) {
    const bool replaceable = p.source_block >= 0 && in.program->blocks[p.source_block].replaceable;
    if (replaceable) {
      ToolPose made = Derived(p);
      made.p_w_tip += Eigen::Vector3d(0.01, 0.02, 0.0);
      out.poses.push_back(made);
      ToolPose moved = p;
      moved.p_w_tip.z() += 0.005;
      moved.feed_mm_per_min *= 0.5;
      out.poses.push_back(moved);
    } else {
      out.poses.push_back(p);
    }
  }
  return out;
}

TEST(AptProgramTest, SmoothedProgramKeepsEveryRecordAndKeptMoveInOrder) {
  for (const char* name : kCorpus) {
    const ToolPath in = ReadCorpus(name);
    const ToolPath smoothed = SimulatedSmoothing(in);
    std::string text;
    const Status s = FormatAptProgram(in, smoothed, {}, &text);
    ASSERT_TRUE(s.ok()) << s.message();
    ToolPath back;
    std::vector<std::string> warnings;
    ASSERT_TRUE(Parse(text, &back, &warnings).ok()) << name;
    // Every block of the input but its replaced moves comes out, in order,
    // as written; what is added is GOTOs and FEDRATs only.
    std::vector<std::string> kept;
    for (const ProgramBlock& b : in.program->blocks) {
      if (!b.replaceable) kept.push_back(b.text);
    }
    size_t k = 0;
    for (const ProgramBlock& b : back.program->blocks) {
      if (k < kept.size() && b.text == kept[k]) {
        ++k;
        continue;
      }
      EXPECT_TRUE(b.text.rfind("GOTO/", 0) == 0 || b.text.rfind("FEDRAT/", 0) == 0)
          << name << ": added " << b.text;
    }
    EXPECT_EQ(k, kept.size()) << name
                              << ": kept record missing: " << kept[std::min(k, kept.size() - 1)];
    // Read back, the poses are the smoothed ones, within the decimals.
    ASSERT_EQ(back.poses.size(), smoothed.poses.size()) << name;
    for (size_t i = 0; i < back.poses.size(); ++i) {
      EXPECT_LT((back.poses[i].p_w_tip - smoothed.poses[i].p_w_tip).norm(), 5e-6) << name << i;
      EXPECT_LT((back.poses[i].a_w - smoothed.poses[i].a_w).norm(), 1e-8) << name << i;
      EXPECT_NEAR(back.poses[i].feed_mm_per_min, smoothed.poses[i].feed_mm_per_min,
                  1e-6 * smoothed.poses[i].feed_mm_per_min)
          << name << i;
      EXPECT_EQ(back.poses[i].rapid, smoothed.poses[i].rapid) << name << i;
    }
  }
}

TEST(AptProgramTest, MovedKeptMoveIsRefusedNamingTheLine) {
  const ToolPath in = ReadCorpus("apt_cycle_cutcom.apt");
  ToolPath out = in;
  out.program = in.program;
  for (ToolPose& p : out.poses) {
    if (p.source_line == 16) p.p_w_tip.x() += 0.1;  // a cycle position
  }
  std::string text;
  const Status s = FormatAptProgram(in, out, {}, &text);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("apt_cycle_cutcom.apt:16: the output moved the pose of a move kept"),
            std::string::npos)
      << s.message();
}

TEST(AptProgramTest, CurveRecordsThatMakeNoCurveAreRefused) {
  EXPECT_NE(ErrorOf("GOTO/5,0,0\nCIRCLE/0,0,0,0,0,1,5\nGOTO/0,6,0\n")
                .find("p.cls:2 (CIRCLE ending at line 3): the arc's end point "
                      "lies 6 mm"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/5,0,0\nCIRCLE/0,0,0,0,0,1,5\nFEDRAT/100\nGOTO/0,5,0\n")
                .find("p.cls:2: CIRCLE is not followed by the GOTO"),
            std::string::npos);
  EXPECT_NE(ErrorOf("CIRCLE/0,0,0,0,0,1,5\nGOTO/0,5,0\n").find("p.cls:1: CIRCLE has no start"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/0,0,0\nNURBS/\nKNOT/0,0,1,1\nCNTRL/0,0,0\nCNTRL/"
                    "1,0,0\nCNTRL/2,0,0\n")
                .find("p.cls:2 (NURBS): 4 knots and 3 control points (CNTRL) "
                      "make no curve"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/0,0,0\nNURBS/\nKNOT/0,0,1,1\nCNTRL/1,0,0\nCNTRL/2,0,0\nFINI\n")
                .find("p.cls:2 (NURBS): the curve starts at (1 0 0), not where the "
                      "tool is"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/0,0,0\nKNOT/0,0,1,1\n").find("p.cls:2: KNOT outside a NURBS curve"),
            std::string::npos);
  EXPECT_NE(ErrorOf("GOTO/0,0,0\nNURBS/\nKNOT/0,0,1,1\nCNTRL/0,0\n")
                .find("p.cls:4: CNTRL needs x,y,z[,w] (3 or 4 numbers), got 2"),
            std::string::npos);
}

}  // namespace
}  // namespace tpopt
