// Standing moves: feed moves that do not move the tool tip, such as a pure
// rotary move (`G1 C90` under tool-centre-point control) or the same pose
// programmed twice. Both smoothing methods parameterise a cutting run by the
// tip's arc length, along which such a move has no length: a rotation over
// none is an unbounded d/ds, and a run of 10 mm moves with one made the
// spline's banded system singular (issue 17, item 7). So such a move is kept
// as programmed, with the pose it starts from, and nothing is smoothed
// across it.
#ifndef TPOPT_MODEL_STANDING_MOVES_H_
#define TPOPT_MODEL_STANDING_MOVES_H_

#include "model/path/tool_path.h"

namespace tpopt {

// A feed move whose tip moves less than this is a standing move, mm: a
// micrometre, below any machining tolerance and above the round-off of
// written coordinates (6 decimals in G-code).
constexpr double kStandingMoveMm = 1e-3;

// Marks as held (ToolPose::held) both poses of every standing move of
// `path`: a feed move (not into a rapid target) whose tip moves less than
// kStandingMoveMm. Returns how many standing moves the path has.
int MarkStandingMoves(ToolPath* path);

}  // namespace tpopt

#endif  // TPOPT_MODEL_STANDING_MOVES_H_
