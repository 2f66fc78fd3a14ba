// A natural cubic smoothing spline y = f(s) (Reinsch): minimises
//   sum_i w_i (y_i - f(s_i))^2 + lambda * integral f''(s)^2 ds
// over strictly increasing abscissae s_i. lambda = 0 interpolates. Solved in
// O(n) from the banded system (R + lambda Q^T W^-1 Q) gamma = Q^T y of Green
// & Silverman, where gamma are the second derivatives at the knots. The
// same representation also holds the not-a-knot interpolant
// (InterpolateNotAKnot), whose end second derivatives are not zero.
//
// The smoothing is set by a dimensionless `smoothing` p with
// lambda = p * h^3, h the mean knot spacing: f'' ~ y / h^2 at the scale of
// the spacing, so the penalty term is then p times the data term whatever
// the units of s and the density of the points.
#ifndef TPOPT_SOLVER_SMOOTHING_SPLINE_H_
#define TPOPT_SOLVER_SMOOTHING_SPLINE_H_

#include <array>
#include <memory>
#include <vector>

#include "model/base/status.h"

namespace tpopt {

class ReinschSystem;

class SmoothingSpline {
 public:
  // Fits. Preconditions checked (error names the index and value): at
  // least 2 points, s strictly increasing and finite, y finite, weights (if
  // given, same size) > 0, smoothing >= 0.
  static Status Fit(const std::vector<double>& s, const std::vector<double>& y,
                    const std::vector<double>& weights, double smoothing, SmoothingSpline* out);

  // Like Fit, with the largest smoothing (bisected on a log scale, to 3 %)
  // whose fit stays within `tolerance` of every y_i with weight >= 1 (points
  // given a smaller weight are free to move). Falls back to interpolation.
  static Status FitWithinTolerance(const std::vector<double>& s, const std::vector<double>& y,
                                   const std::vector<double>& weights, double tolerance,
                                   SmoothingSpline* out);

  // FitWithinTolerance of each series *ys[k] (on the same s and weights)
  // into *outs[k]. The series share one banded system, its set-up and its
  // buffers, as the A and C of a path do.
  static Status FitEachWithinTolerance(const std::vector<double>& s,
                                       const std::vector<const std::vector<double>*>& ys,
                                       const std::vector<double>& weights, double tolerance,
                                       const std::vector<SmoothingSpline*>& outs);

  // Interpolates with not-a-knot ends: the first two intervals are one
  // cubic, and so are the last two (three points: one parabola). Where the
  // data's curve bends at its ends, a natural spline's zero curvature there
  // puts a false bend into the end intervals, the whole third derivative
  // the coarse-to-fine solve's finer level then pays to remove. Same
  // preconditions as Fit without weights.
  static Status InterpolateNotAKnot(const std::vector<double>& s, const std::vector<double>& y,
                                    SmoothingSpline* out);

  // f, f', f'', f''' at s; beyond the fitted range, the straight line along
  // the end's slope (as a natural spline is).
  std::array<double, 4> Evaluate(double s) const;
  double operator()(double s) const { return Evaluate(s)[0]; }

  // Fitted values at the knots.
  const std::vector<double>& values() const { return f_; }
  double smoothing() const { return smoothing_; }

 private:
  // The tolerance fits of the series ys on `system` (inputs checked).
  static Status BisectSmoothing(const std::vector<double>& s,
                                const std::vector<const std::vector<double>*>& ys,
                                const std::vector<double>& weights, double tolerance,
                                ReinschSystem* system, const std::vector<SmoothingSpline*>& outs);
  // Takes the fit of y on `system` (on abscissae s) for lambda, whose
  // second derivatives at the knots, `gamma`, it takes over.
  void Assign(std::shared_ptr<const std::vector<double>> s, const ReinschSystem& system,
              const std::vector<double>& y, double lambda, double smoothing,
              std::vector<double>* gamma);

  // The abscissae, one copy shared by the fits of one FitEachWithinTolerance.
  std::shared_ptr<const std::vector<double>> s_;
  std::vector<double> f_, gamma_;
  double smoothing_ = 0.0;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_SMOOTHING_SPLINE_H_
