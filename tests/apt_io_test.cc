#include "model/apt_io.h"

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

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
  // One warning per unknown major word, at its first line: CUTCOM twice,
  // INSERT twice with different text.
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("p.cls:16: statement 'CUTCOM'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("p.cls:18: statement 'INSERT'"), std::string::npos) << warnings[1];
}

TEST(AptIoTest, NormalisesAxesAndAcceptsCutter) {
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(Parse("CUTTER/10\nGOTO/0,0,0,0,0,2\n", &path, &warnings).ok());
  EXPECT_EQ(path.cutter->radius_mm, 5.0);
  EXPECT_EQ(path.poses[0].a_w, Eigen::Vector3d(0, 0, 1));
}

TEST(AptIoTest, BadInputNamesLineAndValue) {
  EXPECT_NE(ErrorOf("GOTO/1,2,3\nGOTO/1,2,3,0,0\n").find("p.cls:2: GOTO needs 3 or 6 numbers, got 5"),
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
  EXPECT_NE(ErrorOf("GOTO/1,2,3\nGOTO/1,2,3,1,2,3,4\n").find("p.cls:2: GOTO needs 3 or 6 "
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
  EXPECT_NE(ErrorOf("UNITS/INCHES\nGOTO/1,2,3\n").find("p.cls:1: UNITS/INCHES"),
            std::string::npos);
  EXPECT_NE(ErrorOf("TLDATA/MILL,-8,0,20\nGOTO/1,2,3\n").find("p.cls:1: cutter radius -4"),
            std::string::npos);
  EXPECT_NE(ErrorOf("FEDRAT/IPM,20\nGOTO/1,2,3\n").find("IPM"), std::string::npos);
  EXPECT_NE(ErrorOf("").find("no GOTO"), std::string::npos);
}

TEST(AptIoTest, ContinuationSkipsBlankAndCommentLines) {
  // Some posts put a comment between the lines of a continued GOTO; the pose
  // still belongs to the GOTO's own line.
  ToolPath path;
  std::vector<std::string> warnings;
  ASSERT_TRUE(Parse("GOTO/0,0,0\n\nGOTO/1,2,$\n$$ note\n\n  3,0,$\r\n1,0\n", &path, &warnings)
                  .ok());
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
  ASSERT_TRUE(Parse("PARTNO blade 1/2, rev B\ntool   path/FLANK,1\nLOADTL/1\nSPINDL/8000\n"
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
      {"inch.cls", "GOTO/1,2,3\nUNITS/INCHES\n", ":2: UNITS/INCHES is not supported"},
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
  EXPECT_NE(WriteApt(dir.File("e.cls"), path).message().find("e.cls: no poses"),
            std::string::npos);
  path.poses.resize(3);
  path.poses[2].p_w_tip.y() = std::nan("");
  Status s = WriteApt(dir.File("n.cls"), path);
  EXPECT_NE(s.message().find("n.cls: pose 2 cannot be written"), std::string::npos)
      << s.message();
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
      "1.250000000,0.500000000,0.000000000,1,$\n1.750000000,-0.500000000,0.000000000,1,$\n"
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

}  // namespace
}  // namespace tpopt
