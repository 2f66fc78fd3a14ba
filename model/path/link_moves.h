// Link moves: feed moves a program makes to reposition between cuts, such as
// the G1 that indexes from the end of one impeller blade to the start of the
// next at many times the cutting feed. Smoothing treats a link like a rapid
// (its target kept as programmed, nothing smoothed across it) and writes it
// as the feed move it is. Without a stock model the feed is the evidence a
// program gives: a link moves at feed_ratio or more times the median feed of
// the program's feed moves.
#ifndef TPOPT_MODEL_LINK_MOVES_H_
#define TPOPT_MODEL_LINK_MOVES_H_

#include <string>

#include "model/path/tool_path.h"

namespace tpopt {

struct LinkMoveOptions {
  // A feed move at least this many times the median feed is a link; 0 marks
  // none. 0 or > 1.
  double feed_ratio = 10.0;
  bool IsValid(std::string* why) const;
};

// Marks as links, besides the moves the source already marked (the G-code
// reader's kLinkComment), the feed moves at feed_ratio times the median feed
// or more; returns how many links the path has. feed_ratio 0 means no links
// at all and clears every mark. A move without a feed is never marked by its
// feed, and nothing is when fewer than two moves have one.
int MarkLinkMoves(const LinkMoveOptions& options, ToolPath* path);

// How many poses of `path` are link targets.
int CountLinks(const ToolPath& path);

}  // namespace tpopt

#endif  // TPOPT_MODEL_LINK_MOVES_H_
