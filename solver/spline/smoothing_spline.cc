#include "solver/spline/smoothing_spline.h"

#include "solver/spline/reinsch_system.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

// lambda = p h^3, h the mean knot spacing (see smoothing_spline.h).
double Lambda(const std::vector<double>& s, double smoothing) {
  const double mean_h = (s.back() - s.front()) / (static_cast<double>(s.size()) - 1);
  return smoothing * mean_h * mean_h * mean_h;
}

Status SingularError() { return Status::Error("smoothing spline: the banded system is singular"); }

}  // namespace

Status SmoothingSpline::Fit(const std::vector<double>& s, const std::vector<double>& y,
                            const std::vector<double>& weights, double smoothing,
                            SmoothingSpline* out) {
  RETURN_IF_ERROR(CheckInputs(s, y, weights, smoothing));
  ReinschSystem system(s, weights);
  std::vector<double> gamma;
  const double lambda = Lambda(s, smoothing);
  constexpr double kNoTolerance = std::numeric_limits<double>::infinity();
  if (system.Solve(y, lambda, kNoTolerance, &gamma) == ReinschSystem::Outcome::kSingular) {
    return SingularError();
  }
  out->Assign(std::make_shared<const std::vector<double>>(s), system, y, lambda, smoothing,
              &gamma);
  return Status::Ok();
}

Status SmoothingSpline::InterpolateNotAKnot(const std::vector<double>& s,
                                            const std::vector<double>& y, SmoothingSpline* out) {
  RETURN_IF_ERROR(CheckInputs(s, y, {}, 0.0));
  const size_t n = s.size();
  if (n == 2) return Fit(s, y, {}, 0.0, out);
  std::vector<double> h(n - 1), slope(n - 1), m(n, 0.0);
  for (size_t i = 0; i + 1 < n; ++i) {
    h[i] = s[i + 1] - s[i];
    slope[i] = (y[i + 1] - y[i]) / h[i];
  }
  if (n == 3) {
    m.assign(3, 2.0 * (slope[1] - slope[0]) / (h[0] + h[1]));
  } else {
    // Continuity of f'' at the interior knots, h_i-1 m_i-1 + 2 (h_i-1 + h_i)
    // m_i + h_i m_i+1 = 6 (slope_i - slope_i-1), for m_1..m_n-2, with m_0
    // and m_n-1 eliminated by the continuity of f''' at knots 1 and n-2.
    const size_t k = n - 2;
    std::vector<double> sub(k), diag(k), super(k), rhs(k);
    for (size_t r = 0; r < k; ++r) {
      const size_t i = r + 1;
      sub[r] = h[i - 1];
      diag[r] = 2.0 * (h[i - 1] + h[i]);
      super[r] = h[i];
      rhs[r] = 6.0 * (slope[i] - slope[i - 1]);
    }
    const double first = h[0] / h[1], last = h[n - 2] / h[n - 3];
    diag[0] += sub[0] * (1.0 + first);
    super[0] -= sub[0] * first;
    diag[k - 1] += super[k - 1] * (1.0 + last);
    sub[k - 1] -= super[k - 1] * last;
    // Thomas' algorithm (the rows stay diagonally dominant).
    for (size_t r = 1; r < k; ++r) {
      const double w = sub[r] / diag[r - 1];
      diag[r] -= w * super[r - 1];
      rhs[r] -= w * rhs[r - 1];
    }
    m[k] = rhs[k - 1] / diag[k - 1];
    for (size_t r = k - 1; r-- > 0;) m[r + 1] = (rhs[r] - super[r] * m[r + 2]) / diag[r];
    m[0] = (1.0 + first) * m[1] - first * m[2];
    m[n - 1] = (1.0 + last) * m[n - 2] - last * m[n - 3];
  }
  out->s_ = std::make_shared<const std::vector<double>>(s);
  out->f_ = y;
  out->gamma_ = std::move(m);
  out->smoothing_ = 0.0;
  return Status::Ok();
}

Status SmoothingSpline::FitWithinTolerance(const std::vector<double>& s,
                                           const std::vector<double>& y,
                                           const std::vector<double>& weights, double tolerance,
                                           SmoothingSpline* out) {
  return FitEachWithinTolerance(s, {&y}, weights, tolerance, {out});
}

Status SmoothingSpline::FitEachWithinTolerance(const std::vector<double>& s,
                                               const std::vector<const std::vector<double>*>& ys,
                                               const std::vector<double>& weights,
                                               double tolerance,
                                               const std::vector<SmoothingSpline*>& outs) {
  for (const std::vector<double>* y : ys) {
    RETURN_IF_ERROR(CheckInputs(s, *y, weights, 0.0));
  }
  ReinschSystem system(s, weights);
  return BisectSmoothing(s, ys, weights, tolerance, &system, outs);
}

Status SmoothingSpline::BisectSmoothing(const std::vector<double>& s,
                                        const std::vector<const std::vector<double>*>& ys,
                                        const std::vector<double>& weights, double tolerance,
                                        ReinschSystem* system,
                                        const std::vector<SmoothingSpline*>& outs) {
  // Bisection on log10(smoothing) in [-6, 8], every series in step so that
  // their trials share the system's sweeps. 10 halvings of 14 decades find
  // the smoothing to within 3 %; the fit changes by far less than the
  // tolerance over such a step, and every trial costs as much as the rest
  // of the spline method, so finer is waste. Only the best trial's gamma is
  // kept; a failing trial stops at the first point out of tolerance.
  struct Bisection {
    double lo = -6.0, hi = 8.0, mid = 0.0, best_smoothing = 0.0;
    bool found = false;
    std::vector<double> best_gamma, trial_gamma;
  };
  const size_t count = ys.size();
  std::vector<Bisection> b(count);
  std::vector<double> lambdas(count);
  std::vector<std::vector<double>*> trial_gammas(count);
  for (int iter = 0; iter < 10; ++iter) {
    for (size_t k = 0; k < count; ++k) {
      b[k].mid = 0.5 * (b[k].lo + b[k].hi);
      lambdas[k] = Lambda(s, std::pow(10.0, b[k].mid));
      trial_gammas[k] = &b[k].trial_gamma;
    }
    const auto outcomes = system->SolveEach(ys, lambdas, tolerance, trial_gammas);
    for (size_t k = 0; k < count; ++k) {
      switch (outcomes[k]) {
        case ReinschSystem::Outcome::kSingular:
          return SingularError();
        case ReinschSystem::Outcome::kWithin:
          std::swap(b[k].best_gamma, b[k].trial_gamma);
          b[k].best_smoothing = std::pow(10.0, b[k].mid);
          b[k].found = true;
          b[k].lo = b[k].mid;
          break;
        case ReinschSystem::Outcome::kOutside:
          b[k].hi = b[k].mid;
          break;
      }
    }
  }
  const auto shared_s = std::make_shared<const std::vector<double>>(s);
  for (size_t k = 0; k < count; ++k) {
    // No smoothing kept every point: interpolate (lambda = 0, always within).
    if (!b[k].found) {
      RETURN_IF_ERROR(Fit(s, *ys[k], weights, 0.0, outs[k]));
      continue;
    }
    outs[k]->Assign(shared_s, *system, *ys[k], Lambda(s, b[k].best_smoothing),
                    b[k].best_smoothing, &b[k].best_gamma);
  }
  return Status::Ok();
}

void SmoothingSpline::Assign(std::shared_ptr<const std::vector<double>> s,
                             const ReinschSystem& system, const std::vector<double>& y,
                             double lambda, double smoothing, std::vector<double>* gamma) {
  const size_t n = s->size();
  s_ = std::move(s);
  smoothing_ = smoothing;
  f_.resize(n);
  for (size_t i = 0; i < n; ++i) f_[i] = system.Value(y, static_cast<int>(i), lambda, *gamma);
  gamma_ = std::move(*gamma);
}

std::array<double, 4> SmoothingSpline::Evaluate(double x) const {
  const std::vector<double>& s = *s_;
  const int n = static_cast<int>(s.size());
  // Interval i with s_i <= x < s_i+1, clamped to the ends.
  int i = static_cast<int>(std::upper_bound(s.begin(), s.end(), x) - s.begin()) - 1;
  i = std::clamp(i, 0, n - 2);
  const double h = s[i + 1] - s[i];
  const double t = x - s[i];
  const double g0 = gamma_[i], g1 = gamma_[i + 1];
  const double b = (f_[i + 1] - f_[i]) / h - h * (2 * g0 + g1) / 6.0;
  if (x < s.front() || x > s.back()) {
    // Linear beyond the ends, along the end slope (as a natural spline,
    // whose gamma is 0 there, is).
    const bool before = x < s.front();
    const double x0 = before ? s.front() : s.back();
    const auto at_end = Evaluate(x0);
    return {at_end[0] + at_end[1] * (x - x0), at_end[1], 0.0, 0.0};
  }
  const double c = g0 / 2.0, d = (g1 - g0) / (6.0 * h);
  return {f_[i] + t * (b + t * (c + t * d)), b + t * (2 * c + 3 * d * t), 2 * c + 6 * d * t,
          6 * d};
}

}  // namespace tpopt
