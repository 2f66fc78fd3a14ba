#include "solver/fit/bspline_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "model/base/invalid_field.h"

namespace tpopt {
namespace {

constexpr double kMinChordMm = 1e-9;

// Curvature (1/mm) of the circle through three points; 0 when collinear.
double CircleCurvature(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                       const Eigen::Vector3d& p2) {
  const Eigen::Vector3d a = p0 - p1, b = p2 - p1;
  const double denominator = a.norm() * b.norm() * (a - b).norm();
  if (!(denominator > 0.0)) return 0.0;
  return 2.0 * a.cross(b).norm() / denominator;
}

// Sagitta of a chord of `chord_mm` on a circle of curvature `kappa`, written
// so that it does not cancel for small chords.
double SagittaOnCircle(double chord_mm, double kappa) {
  const double half_sine = std::min(1.0, 0.5 * chord_mm * kappa);
  return 0.25 * chord_mm * chord_mm * kappa / (1.0 + std::sqrt(1.0 - half_sine * half_sine));
}

// The three estimated arc lengths of a window's chords, mm.
std::array<double, 3> WindowArcs(const std::array<Eigen::Vector3d, 4>& p,
                                 const std::array<double, 3>& chords,
                                 const LocalFitOptions& options) {
  if (options.chord_height == ChordHeight::kFixed) {
    return {ApproximateArcLength(chords[0], options.chord_height_mm),
            ApproximateArcLength(chords[1], options.chord_height_mm),
            ApproximateArcLength(chords[2], options.chord_height_mm)};
  }
  return {EstimatedArcLength(nullptr, p[0], p[1], &p[2]),
          EstimatedArcLength(&p[0], p[1], p[2], &p[3]),
          EstimatedArcLength(&p[1], p[2], p[3], nullptr)};
}

// Parameter interval of one chord under the parametrisation (unnormalised).
double Interval(Parametrization parametrization, double chord_mm, double arc_mm) {
  switch (parametrization) {
    case Parametrization::kUniform:
      return 1.0;
    case Parametrization::kChordLength:
      return chord_mm;
    case Parametrization::kCentripetal:
      return std::sqrt(chord_mm);
    case Parametrization::kApproximateArc:
      return arc_mm;
  }
  return arc_mm;
}

Status BadPoint(size_t index, const Eigen::Vector3d& value, const std::string& problem) {
  std::ostringstream err;
  err << "CL point " << index << " (" << value.transpose() << "): " << problem;
  return Status::Error(err.str());
}

Status CheckWindow(const std::array<Eigen::Vector3d, 4>& points,
                   const std::array<Eigen::Vector3d, 4>& tangents, size_t first_index) {
  for (size_t k = 0; k < 4; ++k) {
    if (!points[k].allFinite()) return BadPoint(first_index + k, points[k], "not finite");
    // Only the end tangents enter the system (see the header).
    if ((k == 0 || k == 3) &&
        !(tangents[k].allFinite() && std::abs(tangents[k].norm() - 1.0) <= 1e-6)) {
      return BadPoint(first_index + k, tangents[k], "the tangent is not a unit vector");
    }
    if (k > 0 && !((points[k] - points[k - 1]).norm() >= kMinChordMm)) {
      return BadPoint(first_index + k, points[k], "repeats the point before it");
    }
  }
  return Status::Ok();
}

// Blossom values the spans need; names follow the blossom arguments, with
// d_i = C[u_{i+1}, u_{i+2}, u_{i+3}] (d1 = [0,0,a], d2 = [0,a,b],
// d3 = [a,b,1], d4 = [b,1,1]). A blossom is affine in each argument.
struct Blossoms {
  Eigen::Vector3d zero_a_a, a_a_a, a_a_b, a_b_b, b_b_b, b_b_one;
};

Blossoms ComputeBlossoms(const WindowFit& w) {
  const double a = w.knot_a, b = w.knot_b;
  const auto& d = w.control_points;
  Blossoms out;
  out.zero_a_a = d[1] + (a / b) * (d[2] - d[1]);
  out.a_a_b = (1.0 - a) * d[2] + a * d[3];
  out.a_b_b = (1.0 - b) * d[2] + b * d[3];
  out.b_b_one = d[3] + ((b - a) / (1.0 - a)) * (d[4] - d[3]);
  out.a_a_a = out.zero_a_a + (a / b) * (out.a_a_b - out.zero_a_a);
  out.b_b_b = out.a_b_b + ((b - a) / (1.0 - a)) * (out.b_b_one - out.a_b_b);
  return out;
}

}  // namespace

bool LocalFitOptions::IsValid(std::string* why) const {
  if (!(chord_height_mm >= 0.0) || !std::isfinite(chord_height_mm)) {
    if (why) *why = InvalidField("--fit_chord_height_mm", chord_height_mm, "finite and >= 0");
    return false;
  }
  return true;
}

double ApproximateArcLength(double chord_mm, double chord_height_mm) {
  if (!(chord_mm > 0.0)) return 0.0;
  // theta is half the arc's angle: tan(theta / 2) = delta / (L / 2).
  const double theta = 2.0 * std::atan(2.0 * chord_height_mm / chord_mm);
  if (theta < 1e-8) return chord_mm;  // theta / sin(theta) = 1 to double precision
  return chord_mm * theta / std::sin(theta);
}

double EstimatedArcLength(const Eigen::Vector3d* before, const Eigen::Vector3d& p0,
                          const Eigen::Vector3d& p1, const Eigen::Vector3d* after) {
  double kappa = 0.0;
  int circles = 0;
  if (before != nullptr) {
    kappa += CircleCurvature(*before, p0, p1);
    ++circles;
  }
  if (after != nullptr) {
    kappa += CircleCurvature(p0, p1, *after);
    ++circles;
  }
  const double chord = (p1 - p0).norm();
  if (circles == 0) return chord;
  return ApproximateArcLength(chord, SagittaOnCircle(chord, kappa / circles));
}

double ApproximateArcRadius(double chord_mm, double chord_height_mm) {
  if (!(chord_height_mm > 0.0)) return std::numeric_limits<double>::infinity();
  return chord_mm * chord_mm / (8.0 * chord_height_mm) + 0.5 * chord_height_mm;
}

Eigen::Vector3d CubicSpan::Point(double t) const {
  const double s = 1.0 - t;
  return (s * s * s) * bezier[0] + (3.0 * s * s * t) * bezier[1] + (3.0 * s * t * t) * bezier[2] +
         (t * t * t) * bezier[3];
}

Eigen::Vector3d CubicSpan::Derivative(double t) const {
  const double s = 1.0 - t;
  return 3.0 * ((s * s) * (bezier[1] - bezier[0]) + (2.0 * s * t) * (bezier[2] - bezier[1]) +
                (t * t) * (bezier[3] - bezier[2]));
}

std::array<CubicSpan, 3> WindowFit::Spans() const {
  const Blossoms m = ComputeBlossoms(*this);
  const auto& d = control_points;
  return {CubicSpan{{d[0], d[1], m.zero_a_a, m.a_a_a}},
          CubicSpan{{m.a_a_a, m.a_a_b, m.a_b_b, m.b_b_b}},
          CubicSpan{{m.b_b_b, m.b_b_one, d[4], d[5]}}};
}

CubicSpan WindowFit::MiddleSpan(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) const {
  const Blossoms m = ComputeBlossoms(*this);
  // The interpolation conditions make [a,a,a] = P1 and [b,b,b] = P2 up to
  // rounding; the data points themselves make the joins exact.
  return CubicSpan{{p1, m.a_a_b, m.a_b_b, p2}};
}

Status FitWindow(const std::array<Eigen::Vector3d, 4>& p,
                 const std::array<Eigen::Vector3d, 4>& tangents, const LocalFitOptions& options,
                 size_t first_index, WindowFit* fit) {
  RETURN_IF_ERROR(CheckWindow(p, tangents, first_index));
  const std::array<double, 3> chords = {(p[1] - p[0]).norm(), (p[2] - p[1]).norm(),
                                        (p[3] - p[2]).norm()};
  const std::array<double, 3> arcs = WindowArcs(p, chords, options);
  std::array<double, 3> intervals;
  for (int i = 0; i < 3; ++i) intervals[i] = Interval(options.parametrization, chords[i], arcs[i]);
  const double total = intervals[0] + intervals[1] + intervals[2];
  const double a = intervals[0] / total;
  const double b = (intervals[0] + intervals[1]) / total;

  auto& d = fit->control_points;
  d[0] = p[0];
  d[5] = p[3];
  d[1] = p[0] + (arcs[0] / 3.0) * tangents[0];
  d[4] = p[3] - (arcs[2] / 3.0) * tangents[3];
  // C(a) = alpha d1 + beta d2 + gamma d3 and C(b) = beta2 d2 + gamma2 d3 +
  // s^2 d4, from the blossoms (ComputeBlossoms) with r = a/b and
  // s = (b - a)/(1 - a); these are the non-zero basis values N_{i,3}(a) and
  // N_{i,3}(b) of the seed's eq. (10).
  const double r = a / b, q = (b - a) / (1.0 - a);
  const double alpha = (1.0 - r) * (1.0 - r);
  const double beta = (1.0 - r) * r + r * (1.0 - a);
  const double gamma = r * a;
  const double beta2 = (1.0 - q) * (1.0 - b);
  const double gamma2 = (1.0 - q) * b + q * (1.0 - q);
  const Eigen::Vector3d rhs1 = p[1] - alpha * d[1];
  const Eigen::Vector3d rhs2 = p[2] - (q * q) * d[4];
  // The determinant is positive for 0 < a < b < 1 (the matrix is a
  // B-spline collocation matrix at interlacing sites, Schoenberg-Whitney).
  const double det = beta * gamma2 - gamma * beta2;
  d[2] = (gamma2 * rhs1 - gamma * rhs2) / det;
  d[3] = (beta * rhs2 - beta2 * rhs1) / det;
  fit->knot_a = a;
  fit->knot_b = b;
  return Status::Ok();
}

Status FitPolyline(const std::vector<Eigen::Vector3d>& points,
                   const std::vector<Eigen::Vector3d>& unit_tangents,
                   const LocalFitOptions& options, std::vector<CubicSpan>* spans,
                   size_t index_offset) {
  const size_t n = points.size();
  if (n < 4) {
    return Status::Error("a cubic fit needs at least 4 CL points, got " + std::to_string(n));
  }
  if (unit_tangents.size() != n) {
    return Status::Error(std::to_string(unit_tangents.size()) + " tangents for " +
                         std::to_string(n) + " CL points");
  }
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(why);
  spans->clear();
  spans->reserve(n - 1);
  WindowFit fit;
  for (size_t first = 0; first + 3 < n; ++first) {
    const std::array<Eigen::Vector3d, 4> p = {points[first], points[first + 1],
                                              points[first + 2], points[first + 3]};
    const std::array<Eigen::Vector3d, 4> t = {unit_tangents[first], unit_tangents[first + 1],
                                              unit_tangents[first + 2],
                                              unit_tangents[first + 3]};
    RETURN_IF_ERROR(FitWindow(p, t, options, index_offset + first, &fit));
    if (first == 0) {
      CubicSpan head = fit.Spans()[0];
      head.bezier[0] = p[0];
      head.bezier[3] = p[1];
      spans->push_back(head);
    }
    spans->push_back(fit.MiddleSpan(p[1], p[2]));
    if (first + 4 == n) {
      CubicSpan tail = fit.Spans()[2];
      tail.bezier[0] = p[2];
      tail.bezier[3] = p[3];
      spans->push_back(tail);
    }
  }
  return Status::Ok();
}

Status EstimateUnitTangents(const std::vector<Eigen::Vector3d>& points,
                            std::vector<Eigen::Vector3d>* unit_tangents) {
  const size_t n = points.size();
  if (n < 3) {
    return Status::Error("tangents need at least 3 CL points, got " + std::to_string(n));
  }
  for (size_t i = 1; i < n; ++i) {
    if (!((points[i] - points[i - 1]).norm() >= kMinChordMm)) {
      return BadPoint(i, points[i], "repeats the point before it");
    }
  }
  // For x, y, z on one circle, |y - x|^2 (z - x) - |z - x|^2 (y - x) is
  // tangent at x; it points from x towards y and z when both follow x.
  auto circle_tangent_at = [](const Eigen::Vector3d& x, const Eigen::Vector3d& y,
                              const Eigen::Vector3d& z) -> Eigen::Vector3d {
    const Eigen::Vector3d e = y - x, f = z - x;
    return (f.squaredNorm() * e - e.squaredNorm() * f).normalized();
  };
  unit_tangents->resize(n);
  (*unit_tangents)[0] = circle_tangent_at(points[0], points[1], points[2]);
  (*unit_tangents)[n - 1] = -circle_tangent_at(points[n - 1], points[n - 2], points[n - 3]);
  for (size_t i = 1; i + 1 < n; ++i) {
    const Eigen::Vector3d back = points[i - 1] - points[i], ahead = points[i + 1] - points[i];
    (*unit_tangents)[i] =
        (back.squaredNorm() * ahead - ahead.squaredNorm() * back).normalized();
  }
  return Status::Ok();
}

}  // namespace tpopt
