// The banded system (R + lambda Q^T W^-1 Q) gamma = Q^T y of a Reinsch
// smoothing spline (see smoothing_spline.h) for fixed abscissae and
// weights, solved for any data y and lambda.
//
// SmoothingSpline::FitWithinTolerance solves it for about ten lambdas for
// each of several series (the A and C of a path), so what depends on
// neither (1/h, 1/w, the buffers) is set up once here, and one solve is two sweeps over the data: the forward sweep builds
// the LDL^T factor and the forward substitution together, the backward sweep
// finishes gamma and tests the fitted values against the tolerance as it
// goes, stopping at the first point that leaves it. The factor recurrence is
// latency-bound, so the extra arithmetic of the test costs nothing; the
// bands themselves are rebuilt from 1/h and 1/w in registers rather than
// read from memory, which at a million points is what limits a solve.
#ifndef TPOPT_SOLVER_REINSCH_SYSTEM_H_
#define TPOPT_SOLVER_REINSCH_SYSTEM_H_

#include <array>
#include <cstddef>
#include <vector>

namespace tpopt {

class ReinschSystem {
 public:
  // s strictly increasing, weights empty or > 0 and of the same size, at
  // least 2 points (checked by the caller). Keeps references to s and
  // weights, which must outlive it.
  ReinschSystem(const std::vector<double>& s, const std::vector<double>& weights);

  enum class Outcome { kSingular, kWithin, kOutside };

  // gamma, the second derivatives at all n knots (zero at the two ends,
  // the natural spline's), for data y (finite, one per knot) and lambda.
  // kOutside as soon as a point of weight >= 1 (every point without
  // weights) lies further than `tolerance` from its datum; gamma is then
  // incomplete. kSingular when the system is not positive definite.
  Outcome Solve(const std::vector<double>& y, double lambda, double tolerance,
                std::vector<double>* gamma);

  // Solve for each series k (*ys[k], lambdas[k], into *gammas[k]), two at a
  // time in the same sweeps: the factor and back-substitution recurrences
  // are latency-bound, so a second, independent one in the same loop comes
  // almost free.
  std::vector<Outcome> SolveEach(const std::vector<const std::vector<double>*>& ys,
                                 const std::vector<double>& lambdas, double tolerance,
                                 const std::vector<std::vector<double>*>& gammas);

  // Fitted value at point i, y_i - lambda (W^-1 Q gamma)_i, from the
  // gamma of a complete Solve (for row i only gamma[i-1..i+1] are read).
  double Value(const std::vector<double>& y, int i, double lambda,
               const std::vector<double>& gamma) const;

 private:
  // One row of the LDL^T factor: L is unit lower triangular with the two
  // subdiagonals l1, l2 (D, the diagonal, is only needed as z / D).
  struct Pivot {
    double l1, l2;
  };

  // K series at once (K = 1 or 2); pivots_[j * K + k] is row j of series k.
  // z / D, z the forward-substituted rhs, goes where the back substitution
  // will write gamma (knot j + 1 for row j), which then works in place.
  template <int K>
  bool Factor(const std::array<const std::vector<double>*, K>& y,
              const std::array<double, K>& lambda,
              const std::array<std::vector<double>*, K>& gamma);
  template <int K>
  std::array<Outcome, K> BackSubstitute(const std::array<const std::vector<double>*, K>& y,
                                        const std::array<double, K>& lambda, double tolerance,
                                        const std::array<std::vector<double>*, K>& gamma);
  template <int K>
  std::array<Outcome, K> SolveGroup(const std::vector<const std::vector<double>*>& ys,
                                    const std::vector<double>& lambdas, double tolerance,
                                    const std::vector<std::vector<double>*>& gammas,
                                    std::size_t first);
  bool Checked(int i) const { return weights_.empty() || weights_[i] >= 1.0; }

  const std::vector<double>& s_;
  const std::vector<double>& weights_;
  int m_;                                    // interior knots
  std::vector<double> inv_h_, w_inv_;        // 1 / (s_i+1 - s_i), 1 / w_i
  std::vector<Pivot> pivots_;                // the factor of the last solve
};

// Inline: the back substitution tests every row with it.
inline double ReinschSystem::Value(const std::vector<double>& y, int i, double lambda,
                                   const std::vector<double>& gamma) const {
  // Rows take columns i - 2 (its q2), i - 1 (q1) and i (q0), in this order;
  // column j is knot j + 1.
  const double lw = lambda * w_inv_[i];
  double f = y[i];
  if (i >= 2) f -= lw * inv_h_[i - 1] * gamma[i - 1];
  if (i >= 1 && i - 1 < m_) f -= lw * (-inv_h_[i - 1] - inv_h_[i]) * gamma[i];
  if (i < m_) f -= lw * inv_h_[i] * gamma[i + 1];
  return f;
}

}  // namespace tpopt

#endif  // TPOPT_SOLVER_REINSCH_SYSTEM_H_
