#include "model/path/link_moves.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace tpopt {
namespace {

// Poses along X whose moves have the feeds given (pose 0 starts the path).
ToolPath PathWithFeeds(const std::vector<double>& feeds) {
  ToolPath path;
  path.poses.resize(feeds.size() + 1);
  for (size_t i = 0; i < path.poses.size(); ++i) path.poses[i].p_w_tip.x() = double(i);
  for (size_t i = 0; i < feeds.size(); ++i) path.poses[i + 1].feed_mm_per_min = feeds[i];
  return path;
}

TEST(LinkMovesTest, MarksFeedMovesAtTheRatioTimesTheMedianFeed) {
  // Feed moves 100 100 100 110 120 1100 5000 (the rapid's 9000 is not one):
  // median 110, threshold 1100.
  ToolPath path = PathWithFeeds({100, 120, 100, 5000, 110, 9000, 100, 1100});
  path.poses[6].rapid = true;  // a rapid is never a link, whatever its feed
  LinkMoveOptions options;
  EXPECT_EQ(MarkLinkMoves(options, &path), 2);
  for (size_t i = 0; i < path.poses.size(); ++i) {
    EXPECT_EQ(path.poses[i].link, i == 4 || i == 8) << i;  // 1100 is at the threshold
    EXPECT_EQ(IsPositioningMove(path.poses[i]), i == 4 || i == 6 || i == 8) << i;
  }
  // A tighter ratio takes fewer; 0 takes none and clears the marks.
  ToolPath fresh = PathWithFeeds({100, 120, 100, 5000, 110, 9000, 100, 1100});
  fresh.poses[6].rapid = true;
  options.feed_ratio = 20;
  EXPECT_EQ(MarkLinkMoves(options, &fresh), 1);
  EXPECT_TRUE(fresh.poses[4].link);
  EXPECT_FALSE(fresh.poses[8].link);
  options.feed_ratio = 0;
  EXPECT_EQ(MarkLinkMoves(options, &path), 0);
  for (const ToolPose& p : path.poses) EXPECT_FALSE(p.link);
}

// A link the source marked (tpopt's "(link)" in G-code) stays one whatever
// its feed, unless links are off; a rapid or the first pose is never one.
TEST(LinkMovesTest, KeepsTheSourcesMarks) {
  ToolPath path = PathWithFeeds({100, 100, 100, 100});
  path.poses[0].link = true;
  path.poses[2].link = true;
  path.poses[3].link = true;
  path.poses[3].rapid = true;
  EXPECT_EQ(MarkLinkMoves(LinkMoveOptions(), &path), 1);
  EXPECT_TRUE(path.poses[2].link);
  EXPECT_FALSE(path.poses[0].link);
  EXPECT_FALSE(path.poses[3].link);
  LinkMoveOptions off;
  off.feed_ratio = 0;
  EXPECT_EQ(MarkLinkMoves(off, &path), 0);
  EXPECT_FALSE(path.poses[2].link);
}

TEST(LinkMovesTest, MovesWithoutAFeedAreNeverLinks) {
  ToolPath path = PathWithFeeds({0, 0, 0, 100});
  EXPECT_EQ(MarkLinkMoves(LinkMoveOptions(), &path), 0);  // one feed: no median to compare
  path = PathWithFeeds({0, 100, 0, 2000, 0});
  EXPECT_EQ(MarkLinkMoves(LinkMoveOptions(), &path), 0);  // median 2000 of {100, 2000}
  path = PathWithFeeds({0, 100, 100, 2000, 0});
  EXPECT_EQ(MarkLinkMoves(LinkMoveOptions(), &path), 1);
  EXPECT_TRUE(path.poses[4].link);
}

TEST(LinkMovesTest, ValidatesTheRatio) {
  std::string why;
  for (double ok : {0.0, 1.5, 10.0}) {
    LinkMoveOptions o;
    o.feed_ratio = ok;
    EXPECT_TRUE(o.IsValid(&why)) << ok;
  }
  for (double bad : {-1.0, 0.5, 1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    LinkMoveOptions o;
    o.feed_ratio = bad;
    EXPECT_FALSE(o.IsValid(&why)) << bad;
    EXPECT_EQ(why.find("--link_feed_ratio must be 0 (no links) or finite and > 1 (got "), 0u)
        << why;
  }
}

TEST(LinkMovesTest, ADerivedPoseIsAFeedMoveInsideARun) {
  ToolPose link;
  link.link = true;
  link.source_line = 12;
  const ToolPose derived = Derived(link);
  EXPECT_FALSE(derived.link);
  EXPECT_FALSE(derived.rapid);
  EXPECT_EQ(derived.source_line, 0);
}

}  // namespace
}  // namespace tpopt
