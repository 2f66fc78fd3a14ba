// B-spline basis functions shared by curves and tensor-product surfaces:
// clamped knot validation, span search and basis derivatives (Piegl &
// Tiller, The NURBS Book, A2.1 and A2.3).
#ifndef TPOPT_MODEL_BSPLINE_BASIS_H_
#define TPOPT_MODEL_BSPLINE_BASIS_H_

#include <string>
#include <vector>

#include "model/base/status.h"

namespace tpopt {

// Highest degree accepted; evaluation uses fixed-size stack buffers.
constexpr int kMaxBSplineDegree = 15;
// Highest derivative order the evaluators return.
constexpr int kMaxBasisOrder = 3;

// Checks a knot vector for `num_control_points` control points of `degree`
// (1..kMaxBSplineDegree; enough points; n + degree + 1 finite,
// non-decreasing knots; clamped; a non-empty range) and maps it affinely to
// [0, 1]. Messages start with `what` and name the index and value at fault.
Status NormalizeClampedKnots(int degree, size_t num_control_points, const std::string& what,
                             std::vector<double>* knots);

// Index of the knot span holding u in [0, 1] for a normalised clamped knot
// vector: knots[span] <= u < knots[span + 1], the last non-empty span at
// u = 1.
int FindKnotSpan(const std::vector<double>& knots, int degree, int num_control_points, double u);

// ders[k][j] = d^k N_{span - degree + j} / du^k at u, for k = 0..max_order
// (<= kMaxBasisOrder; orders above the degree are zero) and j = 0..degree.
using BasisDerivatives = double[kMaxBasisOrder + 1][kMaxBSplineDegree + 1];
void ComputeBasisDerivatives(const std::vector<double>& knots, int degree, int span, double u,
                             int max_order, BasisDerivatives ders);

}  // namespace tpopt

#endif  // TPOPT_MODEL_BSPLINE_BASIS_H_
