// The two ways around the A = 0 pole.
//
// Where a flank path's tool axis passes close to +Z (the pole of the A/C
// table), its azimuth (C on the machine) sweeps fast, and the path can go
// round the pole on either side: C turning by some angle D one way, or by
// D - 360 deg the other. The two are separate basins of the high-accuracy
// cost: to move from one to the other the axis would have to cross the
// pole, which Levenberg–Marquardt, a local method, does not do. So the
// side the initial guess takes is the side the solve keeps, and a CAM path
// distorted by a degree or two near the pole (or the spline guess made from
// it) can take the wrong one, and the solve then buys smooth C motion with
// an undercut (README, "Figures behind the defaults").
//
// A passage is a stretch of cutting moves along which the axis stays
// within `pole_angle` of +Z and its azimuth turns by at least a quarter
// turn (a smaller sweep has no plausible other way round: that would be a
// sweep of over 270 deg). The rerouted guess keeps each pose's polar angle
// and turns the azimuth the other way, scaled linearly along the passage so
// that it still ends where it did, and pivots each cutter about the middle
// of its flute so the flank stays near the surface.
#ifndef TPOPT_SOLVER_POLE_PASSAGE_H_
#define TPOPT_SOLVER_POLE_PASSAGE_H_

#include <vector>

#include "model/cutter/cutter.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct PolePassage {
  size_t first = 0;                // first pose of the stretch
  size_t last = 0;                 // last pose (inclusive)
  double azimuth_sweep_rad = 0.0;  // net turn of the azimuth, unwrapped
};

// Passages of `path` in order; stretches do not span rapids or links.
std::vector<PolePassage> FindPolePassages(const ToolPath& path,
                                          double pole_angle_rad);

// `path` with `passage` taken round the other side of the pole.
ToolPath RerouteAroundPole(const ToolPath& path, const PolePassage& passage,
                           const Cutter& cutter);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_POLE_PASSAGE_H_
