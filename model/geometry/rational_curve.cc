#include "model/geometry/rational_curve.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "model/geometry/bspline_curve.h"

namespace tpopt {
namespace {

// A bound on memory for curves no CAM system writes (a metre-sized curve at
// 0.001 mm needs some thousands).
constexpr size_t kMaxPoints = 1000000;

// The curve as two non-rational B-splines on the same knots: the weighted
// control points w_i P_i, and the weights (in x). Their ratio is the NURBS
// (Piegl & Tiller, eq. 4.5), so BSplineCurve evaluates both.
struct Homogeneous {
  BSplineCurve weighted;
  BSplineCurve weight;
  Eigen::Vector3d At(double t) const { return weighted.Point(t) / weight.Point(t).x(); }
};

Status Build(const RationalCurve& curve, const std::string& what, Homogeneous* h) {
  const size_t n = curve.control_points.size();
  std::ostringstream err;
  err << what << ": ";
  if (!curve.weights.empty() && curve.weights.size() != n) {
    err << "NURBS has " << curve.weights.size() << " weights for " << n << " control points";
    return Status::Error(err.str());
  }
  std::vector<Eigen::Vector3d> weighted(n), weight(n);
  for (size_t i = 0; i < n; ++i) {
    const double w = curve.weights.empty() ? 1.0 : curve.weights[i];
    if (!(std::isfinite(w) && w > 0.0)) {
      err << "NURBS weight " << i + 1 << " (" << w << ") must be finite and > 0";
      return Status::Error(err.str());
    }
    weighted[i] = w * curve.control_points[i];
    weight[i] = Eigen::Vector3d(w, 0.0, 0.0);
  }
  Status s =
      BSplineCurve::Create(curve.degree, curve.knots, weighted, what + ": NURBS", &h->weighted);
  if (s.ok()) s = BSplineCurve::Create(curve.degree, curve.knots, weight, what, &h->weight);
  return s;
}

// Distance from q to the segment a-b.
double DistanceToChord(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                       const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((q - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (q - (a + t * ab)).norm();
}

void Subdivide(const Homogeneous& h, double t0, double t1, const Eigen::Vector3d& p0,
               const Eigen::Vector3d& p1, double tolerance, int depth,
               std::vector<Eigen::Vector3d>* points) {
  double worst = 0.0;
  for (double f : {0.25, 0.5, 0.75}) {
    worst = std::max(worst, DistanceToChord(h.At(t0 + f * (t1 - t0)), p0, p1));
  }
  // 2^-40 of the range is below any chord a machine can tell apart; past
  // kMaxPoints the caller refuses the curve.
  if (worst <= tolerance || depth >= 40 || points->size() > kMaxPoints) {
    points->push_back(p1);
    return;
  }
  const double tm = 0.5 * (t0 + t1);
  const Eigen::Vector3d pm = h.At(tm);
  Subdivide(h, t0, tm, p0, pm, tolerance, depth + 1, points);
  Subdivide(h, tm, t1, pm, p1, tolerance, depth + 1, points);
}

}  // namespace

Status RationalCurvePoints(const RationalCurve& curve, double chord_tolerance_mm,
                           const std::string& what, std::vector<Eigen::Vector3d>* points) {
  if (!(chord_tolerance_mm > 0.0)) {
    return Status::Error(what + ": chord tolerance must be > 0");
  }
  Homogeneous h;
  RETURN_IF_ERROR(Build(curve, what, &h));
  points->clear();
  // Start from the knot spans, so that no span is skipped by a chord whose
  // quarter points happen to lie on the curve.
  const std::vector<double>& knots = h.weight.knots();
  double t0 = 0.0;
  Eigen::Vector3d p0 = h.At(0.0);
  for (size_t k = curve.degree + 1; k < knots.size() - curve.degree; ++k) {
    if (knots[k] <= t0) continue;
    const Eigen::Vector3d p1 = h.At(knots[k]);
    Subdivide(h, t0, knots[k], p0, p1, chord_tolerance_mm, 0, points);
    if (points->size() > kMaxPoints) {
      return Status::Error(what + ": NURBS needs more than " + std::to_string(kMaxPoints) +
                           " points within " + std::to_string(chord_tolerance_mm) + " mm");
    }
    t0 = knots[k];
    p0 = p1;
  }
  return Status::Ok();
}

Eigen::Vector3d RationalCurvePoint(const RationalCurve& curve, double t) {
  Homogeneous h;
  CHECK(Build(curve, "curve", &h).ok()) << "RationalCurvePoint on an invalid curve";
  return h.At(t);
}

}  // namespace tpopt
