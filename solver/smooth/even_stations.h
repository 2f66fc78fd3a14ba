// The stations of high-accuracy mode: where along the programmed motion each
// pose of a cutting stretch is solved.
//
// A CAM system spaces its poses unevenly (by its own chordal rule, by the
// U/V parametrisation, with pairs a micrometre apart), and the error of the
// controller's straight move between two flank poses on a twisted surface
// grows with the square of the move's length. Solved at the program's own
// stations, a path is only as exact as its longest move, and the solver
// buys back the longest moves' error by bending the axes pose to pose
// (issue 16; README, "Random cases", stop 26). So before the solve, the
// interior poses of every cutting stretch are moved along the input's own
// motion (the controller's interpolation between its poses) so that every
// move makes the same error: a move of length h through contact u errs by
// about h^2 M(u), M from the
// rail's curvature and the turn of the ruling along it, so the steps go as
// 1 / sqrt(M), M floored at its mean over the stretch (where the surface is
// nearly flat, the steps are even in arc length). The stretch's first and
// last poses stay where they are, and (unless the moves are split, below)
// so does the pose count and every block's place in the program.
//
// A stretch is a maximal run of cutting moves (no rapid, link or held
// move: model/path/tool_path.h) of one tool between poses on the surface:
// lead-in and lead-out poses beyond the rail's ends (model/path/
// rail_projection.h) keep their place, which the lead band holds them to.
#ifndef TPOPT_SOLVER_EVEN_STATIONS_H_
#define TPOPT_SOLVER_EVEN_STATIONS_H_

#include "model/base/status.h"
#include "model/geometry/ruled_surface.h"
#include "model/machine/interpolation.h"
#include "model/machine/machine.h"
#include "model/path/tool_path.h"

namespace tpopt {

// `path` with the interior poses of each cutting stretch at the stations
// above along its motion under `interpolation` on `machine`; only their tips
// and axes (and the programmed joints they no longer have) change. With
// `moves_per_move` > 1 each stretch of m moves gets m * moves_per_move, at
// the same equal error: every moves_per_move-th pose is the program's (so
// still one per block), and those between are new poses (Derived) of the
// move into the next. Fails where `path`'s joints cannot be assigned (it
// must fit `machine`) or moves_per_move < 1.
Status EvenStations(const ToolPath& path, const RuledSurface& surface, const Machine& machine,
                    Interpolation interpolation, int moves_per_move, ToolPath* out);

// The farthest the tip strays from the straight line between a cutting
// move's two poses at the middle of the move when the controller moves the
// joints linearly (model/machine/interpolation.h), over the cutting moves of
// `path` that EvenStations spaces, mm: what joint interpolation adds to a
// move's error (0 under TCP). Fails where `path`'s joints cannot be assigned.
Status LargestJointBowMm(const ToolPath& path, const RuledSurface& surface, const Machine& machine,
                         double* bow_mm);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_EVEN_STATIONS_H_
