#include "model/path/program.h"

#include <gtest/gtest.h>

#include "model/machine/machine.h"
#include "model/path/tool_path.h"
#include "solver/smooth/resample.h"

namespace tpopt {
namespace {

// A program of 8 blocks and 5 poses along X:
//   0 (comment)            no pose
//   1 G0 X0                pose 0, rapid, verbatim
//   2 G1 X1 F100           pose 1, replaceable
//   3 X2                   pose 2, replaceable
//   4 X3                   pose 3, replaceable
//   5 M5                   no pose
//   6 X4                   pose 4, held (after M5), verbatim
//   7 M30                  no pose
struct Fixture {
  Program program;
  ToolPath path;
};

Fixture MakeFixture() {
  Fixture f;
  f.program.file = "p.ngc";
  const std::vector<std::pair<std::string, int>> blocks = {
      {"(comment)", -1}, {"G0 X0", 0}, {"G1 X1 F100", 1}, {"X2", 2},
      {"X3", 3},         {"M5", -1},   {"X4", 4},         {"M30", -1}};
  for (size_t b = 0; b < blocks.size(); ++b) {
    ProgramBlock block;
    block.line = static_cast<int>(b) + 1;
    block.text = blocks[b].first;
    block.pose = blocks[b].second;
    block.replaceable = b >= 2 && b <= 4;
    f.program.blocks.push_back(block);
  }
  for (int i = 0; i < 5; ++i) {
    ToolPose pose;
    pose.p_w_tip.x() = i;
    pose.feed_mm_per_min = i == 0 ? 0.0 : 100.0;
    pose.rapid = i == 0;
    pose.held = i == 4;
    pose.source_block = i == 0 ? 1 : i == 4 ? 6 : i + 1;
    f.path.poses.push_back(pose);
  }
  return f;
}

std::vector<int> Blocks(const std::vector<ProgramItem>& items) {
  std::vector<int> blocks;
  for (const ProgramItem& item : items) blocks.push_back(item.block);
  return blocks;
}

TEST(ProgramTest, AnUnchangedPathGivesEveryBlockBackInOrder) {
  const Fixture f = MakeFixture();
  std::vector<ProgramItem> items;
  ASSERT_TRUE(SpliceProgram(f.program, f.path, f.path, &items).ok());
  EXPECT_EQ(Blocks(items), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  for (const ProgramItem& item : items) EXPECT_EQ(item.pose, -1);
}

TEST(ProgramTest, AMovedPoseReplacesItsBlockAndTheOthersStay) {
  const Fixture f = MakeFixture();
  ToolPath out = f.path;
  out.poses[2].p_w_tip.y() = 0.01;  // smoothing moved pose 2 (block 3)
  std::vector<ProgramItem> items;
  ASSERT_TRUE(SpliceProgram(f.program, f.path, out, &items).ok());
  ASSERT_EQ(items.size(), 8u);
  EXPECT_EQ(items[3].block, -1);
  EXPECT_EQ(items[3].pose, 2);
  EXPECT_EQ(Blocks(items), (std::vector<int>{0, 1, 2, -1, 4, 5, 6, 7}));
}

TEST(ProgramTest, ResampledRunReplacesItsMovesAndKeepsEveryOtherBlock) {
  const Fixture f = MakeFixture();
  // The cutting run is poses 0-3 (pose 4 is held); a 0.5 mm step makes 7
  // poses of it, its two ends the source's own.
  ResampleOptions options;
  options.step_mm = 0.5;
  ToolPath out;
  ASSERT_TRUE(ResamplePath(f.path, Machine(), options, &out).ok());
  ASSERT_EQ(out.poses.size(), 8u);
  std::vector<ProgramItem> items;
  ASSERT_TRUE(SpliceProgram(f.program, f.path, out, &items).ok());
  // Comment, rapid, 5 new poses for blocks 2 and 3, block 4 (its pose the
  // run's end, unchanged), M5, the held move, M30.
  std::vector<ProgramItem> expected = {{0, -1}, {1, -1}};
  for (int j = 1; j <= 5; ++j) expected.push_back({-1, j});
  for (int b : {4, 5, 6, 7}) expected.push_back({b, -1});
  ASSERT_EQ(items.size(), expected.size());
  for (size_t k = 0; k < items.size(); ++k) {
    EXPECT_EQ(items[k].block, expected[k].block) << k;
    EXPECT_EQ(items[k].pose, expected[k].pose) << k;
  }
  for (int j = 1; j <= 5; ++j) EXPECT_NEAR(out.poses[j].p_w_tip.x(), 0.5 * j, 1e-9) << j;
}

TEST(ProgramTest, RefusesAnOutputThatMovedAMoveKeptAsProgrammed) {
  const Fixture f = MakeFixture();
  ToolPath out = f.path;
  out.poses[4].p_w_tip.y() = 0.01;
  std::vector<ProgramItem> items;
  Status s = SpliceProgram(f.program, f.path, out, &items);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("p.ngc:7:"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("moved"), std::string::npos) << s.message();

  out = f.path;
  out.poses.erase(out.poses.begin());  // the rapid's pose lost
  s = SpliceProgram(f.program, f.path, out, &items);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("p.ngc:2:"), std::string::npos) << s.message();
}

TEST(ProgramTest, RefusesPosesOutOfOrderOrNamingNoPoseBlock) {
  const Fixture f = MakeFixture();
  ToolPath out = f.path;
  std::swap(out.poses[2], out.poses[3]);
  std::vector<ProgramItem> items;
  EXPECT_FALSE(SpliceProgram(f.program, f.path, out, &items).ok());
  out = f.path;
  out.poses[2].source_block = 5;  // M5 has no pose
  EXPECT_FALSE(SpliceProgram(f.program, f.path, out, &items).ok());
}

TEST(ProgramTest, DerivedPosesAndPathCopiesKeepWhatTheyShould) {
  Fixture f = MakeFixture();
  const ToolPose d = Derived(f.path.poses[4]);
  EXPECT_EQ(d.source_block, -1);
  EXPECT_FALSE(d.held);
  EXPECT_TRUE(IsPositioningMove(f.path.poses[4]));  // held breaks runs
  EXPECT_EQ(RunEnd(f.path, 0), 4u);
  f.path.program = std::make_shared<const Program>(f.program);
  EXPECT_EQ(WithoutPoses(f.path).program, f.path.program);
}

}  // namespace
}  // namespace tpopt
