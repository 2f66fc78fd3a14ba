#include "solver/smoothing_spline.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace tpopt {
namespace {

Status CheckInputs(const std::vector<double>& s, const std::vector<double>& y,
                   const std::vector<double>& w, double smoothing) {
  std::ostringstream err;
  if (s.size() < 2 || s.size() != y.size() || (!w.empty() && w.size() != s.size())) {
    err << "smoothing spline: need >= 2 points and matching sizes (s " << s.size() << ", y "
        << y.size() << ", w " << w.size() << ")";
    return Status::Error(err.str());
  }
  for (size_t i = 0; i < s.size(); ++i) {
    if (!std::isfinite(s[i]) || !std::isfinite(y[i]) || (i > 0 && !(s[i] > s[i - 1]))) {
      err << "smoothing spline: point " << i << " (s " << s[i] << ", y " << y[i]
          << ") is not finite or s does not increase";
      return Status::Error(err.str());
    }
    if (!w.empty() && !(w[i] > 0)) {
      err << "smoothing spline: weight " << i << " = " << w[i] << " must be > 0";
      return Status::Error(err.str());
    }
  }
  if (!(smoothing >= 0) || !std::isfinite(smoothing)) {
    err << "smoothing spline: smoothing " << smoothing << " must be >= 0";
    return Status::Error(err.str());
  }
  return Status::Ok();
}

// `v` resized to `size` zeros, keeping its capacity.
std::vector<double>& Zeroed(size_t size, std::vector<double>* v) {
  v->assign(size, 0.0);
  return *v;
}

}  // namespace

// The banded system's buffers, kept between the trial fits of
// FitWithinTolerance: a million-point run would otherwise fault in a
// hundred megabytes of fresh pages per trial.
struct SmoothingSpline::Scratch {
  std::vector<double> h, q0, q1, q2, w_inv, d0, d1, d2, rhs, dd, l1, l2, gamma;
};

Status SmoothingSpline::Fit(const std::vector<double>& s, const std::vector<double>& y,
                            const std::vector<double>& weights, double smoothing,
                            SmoothingSpline* out) {
  Scratch scratch;
  return FitWithScratch(s, y, weights, smoothing, &scratch, out);
}

Status SmoothingSpline::FitWithScratch(const std::vector<double>& s, const std::vector<double>& y,
                                       const std::vector<double>& weights, double smoothing,
                                       Scratch* scratch, SmoothingSpline* out) {
  Status st = CheckInputs(s, y, weights, smoothing);
  if (!st.ok()) return st;
  const int n = static_cast<int>(s.size());
  std::vector<double>& h = Zeroed(n - 1, &scratch->h);
  for (int i = 0; i + 1 < n; ++i) h[i] = s[i + 1] - s[i];
  const double mean_h = (s.back() - s.front()) / (n - 1);
  const double lambda = smoothing * mean_h * mean_h * mean_h;
  out->s_ = s;
  out->smoothing_ = smoothing;
  out->gamma_.assign(n, 0.0);
  if (n == 2) {
    out->f_ = y;
    return Status::Ok();
  }
  // Q (n x m) and R (m x m), m = n - 2 interior knots; column j of Q is
  // knot j + 1 and has three entries, at rows j, j + 1, j + 2. The system
  // R + lambda Q^T W^-1 Q is symmetric pentadiagonal: assemble its three
  // diagonals directly and factor it by banded LDL^T, O(n) with no fill.
  const int m = n - 2;
  std::vector<double>& q0 = Zeroed(m, &scratch->q0);
  std::vector<double>& q1 = Zeroed(m, &scratch->q1);
  std::vector<double>& q2 = Zeroed(m, &scratch->q2);
  std::vector<double>& w_inv = Zeroed(n, &scratch->w_inv);
  for (int i = 0; i < n; ++i) w_inv[i] = weights.empty() ? 1.0 : 1.0 / weights[i];
  for (int j = 0; j < m; ++j) {
    q0[j] = 1.0 / h[j];
    q1[j] = -1.0 / h[j] - 1.0 / h[j + 1];
    q2[j] = 1.0 / h[j + 1];
  }
  std::vector<double>& d0 = Zeroed(m, &scratch->d0);
  std::vector<double>& d1 = Zeroed(m, &scratch->d1);
  std::vector<double>& d2 = Zeroed(m, &scratch->d2);
  std::vector<double>& rhs = Zeroed(m, &scratch->rhs);
  for (int j = 0; j < m; ++j) {
    d0[j] = (h[j] + h[j + 1]) / 3.0 +
            lambda * (q0[j] * q0[j] * w_inv[j] + q1[j] * q1[j] * w_inv[j + 1] +
                      q2[j] * q2[j] * w_inv[j + 2]);
    if (j + 1 < m) {
      d1[j] = h[j + 1] / 6.0 +
              lambda * (q1[j] * q0[j + 1] * w_inv[j + 1] + q2[j] * q1[j + 1] * w_inv[j + 2]);
    }
    if (j + 2 < m) d2[j] = lambda * q2[j] * q0[j + 2] * w_inv[j + 2];
    rhs[j] = q0[j] * y[j] + q1[j] * y[j + 1] + q2[j] * y[j + 2];
  }
  // LDL^T of the pentadiagonal matrix: L has unit diagonal and two
  // subdiagonals l1, l2; D is diagonal.
  std::vector<double>& dd = Zeroed(m, &scratch->dd);
  std::vector<double>& l1 = Zeroed(m, &scratch->l1);
  std::vector<double>& l2 = Zeroed(m, &scratch->l2);
  for (int j = 0; j < m; ++j) {
    double diag = d0[j];
    if (j >= 1) diag -= l1[j - 1] * l1[j - 1] * dd[j - 1];
    if (j >= 2) diag -= l2[j - 2] * l2[j - 2] * dd[j - 2];
    if (!(diag > 0)) return Status::Error("smoothing spline: the banded system is singular");
    dd[j] = diag;
    if (j + 1 < m) {
      double off = d1[j];
      if (j >= 1) off -= l2[j - 1] * l1[j - 1] * dd[j - 1];
      l1[j] = off / diag;
    }
    if (j + 2 < m) l2[j] = d2[j] / diag;
  }
  std::vector<double>& gamma = scratch->gamma;
  gamma = rhs;
  for (int j = 0; j < m; ++j) {  // L z = rhs
    if (j >= 1) gamma[j] -= l1[j - 1] * gamma[j - 1];
    if (j >= 2) gamma[j] -= l2[j - 2] * gamma[j - 2];
  }
  for (int j = 0; j < m; ++j) gamma[j] /= dd[j];
  for (int j = m - 1; j >= 0; --j) {  // L^T x = z / D
    if (j + 1 < m) gamma[j] -= l1[j] * gamma[j + 1];
    if (j + 2 < m) gamma[j] -= l2[j] * gamma[j + 2];
  }
  // f = y - lambda W^-1 Q gamma.
  out->f_ = y;
  for (int j = 0; j < m; ++j) {
    out->f_[j] -= lambda * w_inv[j] * q0[j] * gamma[j];
    out->f_[j + 1] -= lambda * w_inv[j + 1] * q1[j] * gamma[j];
    out->f_[j + 2] -= lambda * w_inv[j + 2] * q2[j] * gamma[j];
  }
  for (int j = 0; j < m; ++j) out->gamma_[j + 1] = gamma[j];
  return Status::Ok();
}

Status SmoothingSpline::FitWithinTolerance(const std::vector<double>& s,
                                           const std::vector<double>& y,
                                           const std::vector<double>& weights, double tolerance,
                                           SmoothingSpline* out) {
  auto within = [&](const SmoothingSpline& fit) {
    for (size_t i = 0; i < y.size(); ++i) {
      if ((weights.empty() || weights[i] >= 1.0) && std::abs(fit.f_[i] - y[i]) > tolerance) {
        return false;
      }
    }
    return true;
  };
  // Bisection on log10(smoothing) in [-6, 8].
  double lo = -6.0, hi = 8.0;
  Scratch scratch;
  SmoothingSpline best, trial;
  Status st = FitWithScratch(s, y, weights, 0.0, &scratch, &best);
  if (!st.ok()) return st;
  // 10 halvings of 14 decades find the smoothing to within 3 %; the fit
  // changes by far less than the tolerance over such a step, and every fit
  // costs as much as the rest of the spline method, so finer is waste.
  for (int iter = 0; iter < 10; ++iter) {
    const double mid = 0.5 * (lo + hi);
    st = FitWithScratch(s, y, weights, std::pow(10.0, mid), &scratch, &trial);
    if (!st.ok()) return st;
    if (within(trial)) {
      std::swap(best, trial);  // trial keeps the old buffers for the next try
      lo = mid;
    } else {
      hi = mid;
    }
  }
  *out = std::move(best);
  return Status::Ok();
}

std::array<double, 4> SmoothingSpline::Evaluate(double x) const {
  const int n = static_cast<int>(s_.size());
  // Interval i with s_i <= x < s_i+1, clamped to the ends.
  int i = static_cast<int>(std::upper_bound(s_.begin(), s_.end(), x) - s_.begin()) - 1;
  i = std::clamp(i, 0, n - 2);
  const double h = s_[i + 1] - s_[i];
  const double t = x - s_[i];
  const double g0 = gamma_[i], g1 = gamma_[i + 1];
  const double b = (f_[i + 1] - f_[i]) / h - h * (2 * g0 + g1) / 6.0;
  if (x < s_.front() || x > s_.back()) {
    // Natural spline: linear beyond the ends (gamma = 0 there).
    const bool before = x < s_.front();
    const double x0 = before ? s_.front() : s_.back();
    const auto at_end = Evaluate(x0);
    return {at_end[0] + at_end[1] * (x - x0), at_end[1], 0.0, 0.0};
  }
  const double c = g0 / 2.0, d = (g1 - g0) / (6.0 * h);
  return {f_[i] + t * (b + t * (c + t * d)), b + t * (2 * c + 3 * d * t), 2 * c + 6 * d * t,
          6 * d};
}

}  // namespace tpopt
