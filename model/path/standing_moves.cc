#include "model/path/standing_moves.h"

namespace tpopt {

int MarkStandingMoves(ToolPath* path) {
  int count = 0;
  for (size_t i = 1; i < path->poses.size(); ++i) {
    ToolPose& to = path->poses[i];
    if (to.rapid) continue;
    if ((to.p_w_tip - path->poses[i - 1].p_w_tip).norm() >= kStandingMoveMm) continue;
    path->poses[i - 1].held = true;
    to.held = true;
    ++count;
  }
  return count;
}

}  // namespace tpopt
