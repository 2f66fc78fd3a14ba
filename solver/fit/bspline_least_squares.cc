#include "solver/fit/bspline_least_squares.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Sparse>

#include "model/geometry/bspline_basis.h"
#include "model/base/invalid_field.h"
#include <Eigen/SparseCholesky>

namespace tpopt {
namespace {

constexpr int kDegree = 3;

// Normalised cumulative parameters of the points.
Status DataParameters(const std::vector<Eigen::Vector3d>& points, Parametrization kind,
                      std::vector<double>* t) {
  const size_t m = points.size();
  std::vector<double> interval(m - 1);
  for (size_t i = 0; i + 1 < m; ++i) {
    const double chord = (points[i + 1] - points[i]).norm();
    if (!(chord >= 1e-9)) {
      return Status::Error("CL point " + std::to_string(i + 1) + " repeats the point before it");
    }
    switch (kind) {
      case Parametrization::kUniform:
        interval[i] = 1.0;
        break;
      case Parametrization::kChordLength:
        interval[i] = chord;
        break;
      case Parametrization::kCentripetal:
        interval[i] = std::sqrt(chord);
        break;
      case Parametrization::kApproximateArc:
        interval[i] = EstimatedArcLength(i > 0 ? &points[i - 1] : nullptr, points[i],
                                         points[i + 1], i + 2 < m ? &points[i + 2] : nullptr);
        break;
    }
  }
  t->assign(m, 0.0);
  for (size_t i = 1; i < m; ++i) (*t)[i] = (*t)[i - 1] + interval[i - 1];
  for (double& x : *t) x /= t->back();
  t->back() = 1.0;
  return Status::Ok();
}

// Knots for n control points by averaging the parameters (eq. 9.69).
std::vector<double> AveragedKnots(const std::vector<double>& t, int n) {
  const int m = static_cast<int>(t.size()) - 1;
  std::vector<double> knots(n + kDegree + 1, 0.0);
  std::fill(knots.end() - (kDegree + 1), knots.end(), 1.0);
  const double d = double(m + 1) / (n - kDegree);
  for (int j = 1; j < n - kDegree; ++j) {
    const int i = static_cast<int>(j * d);
    const double alpha = j * d - i;
    knots[j + kDegree] = (1.0 - alpha) * t[i - 1] + alpha * t[i];
  }
  return knots;
}

// Least-squares curve with n control points; its largest error at the data.
Status SolveForCount(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& t,
                     int n, BSplineCurve* curve, double* max_error) {
  const int m = static_cast<int>(points.size()) - 1;
  std::vector<Eigen::Vector3d> control(n, Eigen::Vector3d::Zero());
  control.front() = points.front();
  control.back() = points.back();
  std::vector<double> knots = AveragedKnots(t, n);
  {
    // Rows: interior points 1..m-1; columns: interior control points 1..n-2.
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m - 1, 3);
    for (int k = 1; k < m; ++k) {
      const int span = FindKnotSpan(knots, kDegree, n, t[k]);
      BasisDerivatives ders;
      ComputeBasisDerivatives(knots, kDegree, span, t[k], 0, ders);
      Eigen::Vector3d r = points[k];
      for (int j = 0; j <= kDegree; ++j) {
        const int col = span - kDegree + j;
        if (col == 0) {
          r -= ders[0][j] * points.front();
        } else if (col == n - 1) {
          r -= ders[0][j] * points.back();
        } else {
          entries.emplace_back(k - 1, col - 1, ders[0][j]);
        }
      }
      rhs.row(k - 1) = r.transpose();
    }
    Eigen::SparseMatrix<double> a(m - 1, n - 2);
    a.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SparseMatrix<double> normal = a.transpose() * a;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success) {
      return Status::Error("the least-squares system with " + std::to_string(n) +
                           " control points is singular");
    }
    const Eigen::MatrixXd x = solver.solve(a.transpose() * rhs);
    for (int j = 1; j + 1 < n; ++j) control[j] = x.row(j - 1).transpose();
  }
  RETURN_IF_ERROR(BSplineCurve::Create(kDegree, knots, control, "least-squares fit", curve));
  *max_error = 0.0;
  for (int k = 0; k <= m; ++k) {
    *max_error = std::max(*max_error, (curve->Point(t[k]) - points[k]).norm());
  }
  return Status::Ok();
}

}  // namespace

bool LeastSquaresFitOptions::IsValid(std::string* why) const {
  if (tolerance_mm > 0 && std::isfinite(tolerance_mm)) return true;
  if (why) *why = InvalidField("tolerance_mm", tolerance_mm, "finite and > 0");
  return false;
}

Status FitLeastSquares(const std::vector<Eigen::Vector3d>& points,
                       const LeastSquaresFitOptions& options, LeastSquaresFit* fit) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(why);
  if (points.size() < 4) {
    return Status::Error("a least-squares fit needs at least 4 points, got " +
                         std::to_string(points.size()));
  }
  RETURN_IF_ERROR(DataParameters(points, options.parametrization, &fit->parameters));
  // Bisection on the control-point count: error falls (almost always) as
  // the count grows, and the count equal to the number of points
  // interpolates.
  int lo = kDegree + 1, hi = static_cast<int>(points.size());
  BSplineCurve curve;
  double error = 0.0;
  Status s = SolveForCount(points, fit->parameters, hi, &curve, &error);
  if (!s.ok()) return s;
  if (error > options.tolerance_mm) {
    return Status::Error("even interpolation misses the tolerance of " +
                         std::to_string(options.tolerance_mm) + " mm");
  }
  fit->curve = curve;
  fit->max_error_mm = error;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    s = SolveForCount(points, fit->parameters, mid, &curve, &error);
    if (s.ok() && error <= options.tolerance_mm) {
      hi = mid;
      fit->curve = curve;
      fit->max_error_mm = error;
    } else {
      lo = mid + 1;
    }
  }
  return Status::Ok();
}

}  // namespace tpopt
