#include "model/apt_io.h"

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

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
  // One warning per unknown word: CUTCOM twice, INSERT once.
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("p.cls:16: statement 'CUTCOM'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("INSERT G05.1 Q1"), std::string::npos) << warnings[1];
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
  EXPECT_NE(ErrorOf("GOTO/1,inf,3\n").find("out of range"), std::string::npos);
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
