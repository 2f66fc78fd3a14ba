// Cutter-location (CL) poses and paths in the workpiece frame W.
#ifndef TPOPT_MODEL_TOOL_PATH_H_
#define TPOPT_MODEL_TOOL_PATH_H_

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/cutter/cutter.h"
#include "model/path/program.h"

namespace tpopt {

// The rotary joints of a machine program, radians: C with its winding
// (whole turns) and its value at A = 0, neither of which a tool axis holds.
struct RotaryJoints {
  double a_rad = 0.0;
  double c_rad = 0.0;
};

struct ToolPose {
  // Tool tip (centre of the cutter's end face) in W, mm.
  Eigen::Vector3d p_w_tip = Eigen::Vector3d::Zero();
  // Unit tool axis in W, from the tip into the spindle.
  Eigen::Vector3d a_w = Eigen::Vector3d::UnitZ();
  // Programmed feed, mm/min; 0 when the source gave none.
  double feed_mm_per_min = 0.0;
  // True for a rapid (positioning) move to this pose.
  bool rapid = false;
  // True for a link: a feed move the program makes to reposition between
  // cuts (model/path/link_moves.h). Written as the feed move it is, but, like a
  // rapid, kept as programmed and never smoothed across.
  bool link = false;
  // True for a move the source program keeps as programmed because a block
  // that smoothing must not cross comes before it or is it (a non-motion
  // block, an arc, a G53 move, a move with other words; model/path/program.h):
  // like a rapid or link target, kept and never smoothed across. Written as
  // its source block.
  bool held = false;
  // 1-based line of the source file the pose came from, 0 if generated.
  int source_line = 0;
  // A and C as the source program gave them (G-code input), if it did.
  // Machine::AssignJoints keeps them while a_w is still the axis they give,
  // so that what a program positions to is written back as programmed.
  std::optional<RotaryJoints> programmed;
  // Index of the block of ToolPath::program this pose is the move of; -1
  // for a pose a method made (or a path with no program).
  int source_block = -1;
  // Index into ToolPath::tools of the tool that makes this move; -1 when
  // the source loads none.
  int tool = -1;
  // G-code: the tool length offset in effect for this move (G43 H, G43.1,
  // G49), mm. LinuxCNC adds it to the programmed Z, and on xyzac-trt-kins
  // wired as the sims are (tool-offset from motion.tooloffset.z) the tip's
  // path in the table frame does not depend on it: only joint Z is this much
  // higher (docs/ARCHITECTURE.md, "Tool length offsets"), which
  // Machine::CheckTravel adds. length_offset_tool is the tool whose table Z
  // it adds (H, or the loaded tool for G43 alone; 0 none, -1 a G43.2 sum
  // tpopt does not resolve); SizeToolsFromTable adds that Z.
  int length_offset_tool = 0;
  double length_offset_mm = 0.0;
};

// True when the move into `pose` is kept as programmed (a rapid, a link or a
// held move): its target is kept, and smoothing and spline runs stop at it
// (high accuracy's smoothness stencils run into a held pose, as its fixed
// end: solver/smooth/ceres_smoother.cc).
inline bool IsPositioningMove(const ToolPose& pose) { return pose.rapid || pose.link || pose.held; }

// A pose a method makes between poses of its source (a sample, an inserted
// transition), starting from a copy of `pose`: a feed move inside a run,
// with no source line, never programmed.
inline ToolPose Derived(ToolPose pose) {
  pose.rapid = false;
  pose.link = false;
  pose.held = false;
  pose.source_line = 0;
  pose.programmed.reset();
  pose.source_block = -1;
  return pose;
}

// A tool as the source program defines it (TLDATA/CUTTER, LOAD/TOOL).
struct ToolRecord {
  // The tool number of LOAD/TOOL or LOADTL; 0 when none was given.
  int number = 0;
  // Diameter (as radius_mm) and flute length, when the source gives them.
  std::optional<Cutter> cutter;
  // Corner radius, mm (TLDATA/MILL,d,r / CUTTER/d,r), in [0, radius]. Kept
  // for the program; the flank model takes the cutter as sharp-cornered.
  double corner_radius_mm = 0.0;
  // 1-based line of the record that defined the tool.
  int source_line = 0;
};

struct ToolPath {
  std::vector<ToolPose> poses;
  // The cutter named by the source (TLDATA/CUTTER), if any: with several
  // tools, the one of the first feed move.
  std::optional<Cutter> cutter;
  // Every tool the source loads, in order (a tool loaded twice is listed
  // twice); ToolPose::tool indexes it.
  std::vector<ToolRecord> tools;
  // Free text carried through to outputs (e.g. the generator's settings).
  std::string title;
  // The program the path was read from, block for block, or null for a path
  // made here (generate, pencil). Shared: derived paths point at the same
  // source, and copying a path does not copy its program.
  std::shared_ptr<const Program> program;
};

// One past the last pose of the cutting run that starts at pose `first`:
// the next rapid or link target, or the end of the path.
inline size_t RunEnd(const ToolPath& path, size_t first) {
  size_t end = first + 1;
  while (end < path.poses.size() && !IsPositioningMove(path.poses[end])) ++end;
  return end;
}

// `path` without its poses, cutter, title and program kept: where a derived
// path starts, without first copying every pose of the original.
inline ToolPath WithoutPoses(const ToolPath& path) {
  ToolPath out;
  out.cutter = path.cutter;
  out.tools = path.tools;
  out.title = path.title;
  out.program = path.program;
  return out;
}

}  // namespace tpopt

#endif  // TPOPT_MODEL_TOOL_PATH_H_
