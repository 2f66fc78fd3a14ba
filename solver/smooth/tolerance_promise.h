// The tolerance promise of high-accuracy mode, judged on the exact swept
// envelope (not the solver's sample points): no grid point of the surface
// may end up farther from the cutter than the tolerance unless the input
// was farther there. The input's "there" is at the resolution of its own
// moves (InputAllowance): a noisy CAM path that touches the surface at one
// grid point between others it leaves tenths of a millimetre off holds no
// tolerance there that a smooth path could keep, and holding a solve to
// that one point put back whole runs with the input's tenths (issue 16).
#ifndef TPOPT_SOLVER_TOLERANCE_PROMISE_H_
#define TPOPT_SOLVER_TOLERANCE_PROMISE_H_

#include <cstddef>
#include <string>
#include <vector>

#include "model/eval/deviation.h"

namespace tpopt {

// Per grid point of `in` (the input's deviation report), what the input left
// across the move that cut it: the largest |deviation| at the grid points
// of the same v whose u lies between the contact rulings of the input's
// poses either side of the point's u (`input_u`: CuttingContactU's, any
// order; at a pose's own ruling, the moves into and out of it), mm. A grid point beyond the poses' range takes the stretch from
// the nearest pose's ruling to itself. All zero when `input_u` is empty.
std::vector<double> InputAllowance(const DeviationReport& in, std::vector<double> input_u);

// The grid points (indices into out.deviation_mm) that break the promise:
// beyond `tolerance_mm` and beyond the input's allowance there (as above,
// one a grid point of `out`) by more than `slack_mm` (the same moves
// evaluated again can differ in the last bits).
std::vector<size_t> BeyondTolerance(const std::vector<double>& allowance_mm,
                                    const DeviationReport& out, double tolerance_mm,
                                    double slack_mm = 0.0);

// Whether the points that break the promise after a solve (`beyond_after`
// of `after`, as BeyondTolerance gives them) are those of the solve before
// (`beyond_before` of `before`), each as far off to within `within_mm`: a
// solve that held them harder moved none of them. False where either is
// empty.
bool SameBeyondPoints(const DeviationReport& before, const std::vector<size_t>& beyond_before,
                      const DeviationReport& after, const std::vector<size_t>& beyond_after,
                      double within_mm);

// Why a result is refused: how many points are beyond, and the worst, with
// the input's own deviation there. `beyond` is not empty.
std::string BeyondToleranceMessage(const DeviationReport& in, const DeviationReport& out,
                                   const std::vector<size_t>& beyond, double tolerance_mm);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_TOLERANCE_PROMISE_H_
