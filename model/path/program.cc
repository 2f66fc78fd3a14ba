#include "model/path/program.h"

#include <sstream>

#include "model/path/tool_path.h"

namespace tpopt {
namespace {

// Smoothing copies the poses it keeps; anything beyond round-off is a move.
bool SamePlace(const ToolPose& a, const ToolPose& b) {
  constexpr double kSame = 1e-12;
  return (a.p_w_tip - b.p_w_tip).norm() <= kSame && (a.a_w - b.a_w).norm() <= kSame;
}

// A move that can be written as its source block: the same place and feed.
// (A verbatim block's feed is its own whatever a schedule made of it: feed
// scheduling fills in every move's feed, rapids' included.)
bool SameMove(const ToolPose& a, const ToolPose& b) {
  return SamePlace(a, b) && a.feed_mm_per_min == b.feed_mm_per_min && a.rapid == b.rapid &&
         a.link == b.link;
}

Status Misfit(const Program& program, const ProgramBlock& block, const std::string& what) {
  std::ostringstream err;
  err << program.file << ":" << block.line << ": " << what;
  return Status::Error(err.str());
}

}  // namespace

Status SpliceProgram(const Program& program, const ToolPath& input, const ToolPath& output,
                     std::vector<ProgramItem>* items) {
  const int n_blocks = static_cast<int>(program.blocks.size());
  int last_block = -1;
  for (size_t j = 0; j < output.poses.size(); ++j) {
    const int b = output.poses[j].source_block;
    if (b < 0) continue;
    if (b >= n_blocks || b <= last_block || program.blocks[b].pose < 0 ||
        program.blocks[b].pose >= static_cast<int>(input.poses.size())) {
      std::ostringstream err;
      err << program.file << ": output pose " << j << " names source block " << b
          << ", which is out of order or has no pose of the " << input.poses.size()
          << "-pose input";
      return Status::Error(err.str());
    }
    last_block = b;
  }
  std::vector<ProgramItem> out;
  out.reserve(program.blocks.size() + output.poses.size());
  size_t j = 0;
  const size_t n_out = output.poses.size();
  for (int b = 0; b < n_blocks; ++b) {
    const ProgramBlock& block = program.blocks[b];
    if (block.pose < 0) {
      out.push_back({b, -1});
      continue;
    }
    const ToolPose& source = input.poses[block.pose];
    if (!block.replaceable) {
      // Points a reader made along a kept arc or curve (held, of no block)
      // are that block's motion: the block is written, not they.
      while (j < n_out && output.poses[j].source_block < 0 && output.poses[j].held) ++j;
      if (j < n_out && output.poses[j].source_block < 0) {
        return Misfit(program, block, "the output has new poses before a move kept as programmed");
      }
      if (j == n_out || output.poses[j].source_block != b) {
        return Misfit(program, block, "the output lost the pose of a move kept as programmed");
      }
      if (!SamePlace(output.poses[j], source)) {
        return Misfit(program, block, "the output moved the pose of a move kept as programmed");
      }
      out.push_back({b, -1});
      ++j;
      continue;
    }
    while (j < n_out && output.poses[j].source_block < 0)
      out.push_back({-1, static_cast<int>(j++)});
    if (j < n_out && output.poses[j].source_block == b) {
      if (SameMove(output.poses[j], source)) {
        out.push_back({b, -1});
      } else {
        out.push_back({-1, static_cast<int>(j)});
      }
      ++j;
    }
  }
  // Poses a method made after the last source pose it kept (none of the
  // methods does: each keeps the ends of its runs) still go out, in order;
  // the order check above leaves no kept pose here.
  while (j < n_out) out.push_back({-1, static_cast<int>(j++)});
  *items = std::move(out);
  return Status::Ok();
}

}  // namespace tpopt
