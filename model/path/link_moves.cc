#include "model/path/link_moves.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "model/base/invalid_field.h"

namespace tpopt {

bool LinkMoveOptions::IsValid(std::string* why) const {
  if (feed_ratio == 0 || (std::isfinite(feed_ratio) && feed_ratio > 1)) return true;
  if (why != nullptr) {
    *why = InvalidField("--link_feed_ratio", feed_ratio, "0 (no links) or finite and > 1");
  }
  return false;
}

namespace {

// A feed move into pose i (i > 0) with a programmed feed.
bool HasFeed(const ToolPath& path, size_t i) {
  return i > 0 && !path.poses[i].rapid && path.poses[i].feed_mm_per_min > 0;
}

}  // namespace

int MarkLinkMoves(const LinkMoveOptions& options, ToolPath* path) {
  std::vector<double> feeds;
  for (size_t i = 0; i < path->poses.size(); ++i) {
    ToolPose& pose = path->poses[i];
    pose.link = options.feed_ratio > 0 && pose.link && i > 0 && !pose.rapid;
    if (HasFeed(*path, i)) feeds.push_back(pose.feed_mm_per_min);
  }
  if (options.feed_ratio > 0 && feeds.size() >= 2) {
    const auto middle = feeds.begin() + feeds.size() / 2;
    std::nth_element(feeds.begin(), middle, feeds.end());
    const double threshold = options.feed_ratio * *middle;
    for (size_t i = 0; i < path->poses.size(); ++i) {
      if (HasFeed(*path, i) && path->poses[i].feed_mm_per_min >= threshold) {
        path->poses[i].link = true;
      }
    }
  }
  return CountLinks(*path);
}

int CountLinks(const ToolPath& path) {
  return static_cast<int>(std::count_if(path.poses.begin(), path.poses.end(),
                                        [](const ToolPose& p) { return p.link; }));
}

}  // namespace tpopt
