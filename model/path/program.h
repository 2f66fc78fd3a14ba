// The source program a tool path was read from, block for block, so that a
// written program is the user's program with only its smoothed cutting moves
// changed (docs/ARCHITECTURE.md, "File formats").
//
// A reader (G-code, APT) keeps every block of its input in order. A block is
// either written back as it was (comments, spindle, coolant, tool changes,
// rapids, arcs, G53 moves, moves with other words on them, ...) or is a plain
// cutting move that the output may replace. Each move whose end the reader
// can place in W becomes a pose of the ToolPath, and the block and the pose
// name each other (ProgramBlock::pose, ToolPose::source_block).
//
// Smoothing runs never cross a kept block: the reader marks the pose that
// follows one ToolPose::held (a move kept as programmed, like a rapid or link
// target, IsPositioningMove), so the poses on both sides of it stay where the
// program put them and the tool is where the program says when the block
// runs. Within a run, a method may move, drop and add poses; the poses it
// keeps from the source carry their source_block, the ones it makes have -1
// (Derived in tool_path.h). SpliceProgram then lays the output poses into the
// source blocks for a writer.
#ifndef TPOPT_MODEL_PROGRAM_H_
#define TPOPT_MODEL_PROGRAM_H_

#include <memory>
#include <string>
#include <vector>

#include "model/base/status.h"

namespace tpopt {

struct ToolPath;

enum class ProgramFormat { kGcode, kApt };

struct ProgramBlock {
  // 1-based line of the block's first source line.
  int line = 0;
  // The block's source text as read, without its final line break; an APT
  // statement with continuation lines holds them joined by '\n'.
  std::string text;
  // Index into the source ToolPath::poses of the pose this block's move
  // reaches, or -1 when it has none (non-motion blocks; moves the reader
  // cannot place in W, such as G53 moves or moves before every axis is set).
  int pose = -1;
  // True only for a plain cutting move (in G-code: G1 and axis words, F, N,
  // in absolute mode, G93 or G94) that the output may replace by the poses a
  // method made for its run. Every other block is written back verbatim, and
  // its pose, if it has one, must come out of smoothing unchanged.
  bool replaceable = false;
  // Millimetres per length unit of the block's coordinates and feed (25.4
  // for G20 or inch APT): a replaced move is written in its block's units.
  double mm_per_unit = 1.0;
  // G-code: X Y Z are machine joints (joint style, after M429) rather than
  // the tool tip in W (tcp style); a replaced move is written in the style
  // its block had.
  bool machine_joints = false;
  // G-code: the block is in G93 inverse-time feed mode; a replaced move is
  // written with F = 1 / minutes of its planned segment.
  bool inverse_time = false;
  // The feed word in effect after this block in the source, in the block's
  // units per minute (G94; G93: 1 / minutes) as written; 0 when none has
  // been given. A writer
  // that wrote other feeds for replaced moves restores this one before the
  // next verbatim block, which may rely on it being modal.
  double modal_feed = 0.0;
};

struct Program {
  ProgramFormat format = ProgramFormat::kGcode;
  // The file the program was read from, for messages.
  std::string file;
  std::vector<ProgramBlock> blocks;
  // Whether the source's last line ended with a line break.
  bool final_newline = true;
};

// One item of a written program: source block `block` written back as it
// was, or pose `pose` of the output path written as a move. Exactly one of
// the two is >= 0.
struct ProgramItem {
  int block = -1;
  int pose = -1;
};

// Lays the poses of `output`, a path smoothed from `input` (read with
// `program`), into the program's blocks, in order:
//  - a block without a pose, and a verbatim move, is written as it was (a
//    verbatim move's pose must be in `output` at the same place; its feed
//    is the block's own); held poses of no block just before a verbatim
//    move are points a reader made along it (an arc, a spline: the move is
//    more than one pose) and are skipped;
//  - a replaceable move whose pose `output` holds unchanged (position, axis,
//    feed) is written as it was too, so a path that was not smoothed comes
//    back text for text;
//  - otherwise a replaceable move is replaced by the output poses a method
//    made before its own (source_block -1) and its own moved pose, or by none
//    when the method dropped its pose.
// Fails, naming the block's line, when `output` does not fit the program:
// a verbatim move's pose moved or missing, source blocks out of order, a
// pose naming a block the program does not have.
Status SpliceProgram(const Program& program, const ToolPath& input, const ToolPath& output,
                     std::vector<ProgramItem>* items);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PROGRAM_H_
