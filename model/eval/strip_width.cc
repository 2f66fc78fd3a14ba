#include "model/eval/strip_width.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace tpopt {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Newton on (S(u, v) - cc) . f = 0, (S(u, v) - cc) . b = s from *uv.
bool SolveSectionPoint(const ParametricSurface& surface, const CrossSection& section,
                       double s, Eigen::Vector2d* uv, SurfaceDerivatives* at) {
  for (int iteration = 0; iteration < 30; ++iteration) {
    *at = surface.Evaluate(uv->x(), uv->y());
    const Eigen::Vector3d d = at->p - section.cc;
    const Eigen::Vector2d residual(d.dot(section.f), d.dot(section.b) - s);
    if (residual.norm() < 1e-10) return true;
    Eigen::Matrix2d jac;
    jac << at->su.dot(section.f), at->sv.dot(section.f), at->su.dot(section.b),
        at->sv.dot(section.b);
    if (std::abs(jac.determinant()) < 1e-14) return false;
    *uv -= jac.inverse() * residual;
    // Outside the parameter square the section has left the surface.
    if (uv->minCoeff() < -1e-9 || uv->maxCoeff() > 1 + 1e-9) return false;
  }
  return false;
}

// Marches outward from the CC point in one direction (+1 or -1), each
// Newton solve starting from its neighbour; stops at the first failure.
void MarchSide(const ParametricSurface& surface, double u0, double v0, int direction,
               int samples_per_side, CrossSection* section) {
  Eigen::Vector2d uv(u0, v0);
  SurfaceDerivatives at;
  for (int step = 1; step <= samples_per_side; ++step) {
    const int k = section->centre + direction * step;
    if (!SolveSectionPoint(surface, *section, section->s(k), &uv, &at)) return;
    section->points[k] = at.p;
    section->normals[k] = surface.ToolSideNormal(at);
    section->valid[k] = true;
  }
}

// min over t of the distance from q - t f to the cutter: golden section
// over |t| <= bound (the distance is convex in t, see the header).
double SweptDistance(const TorusCutter& cutter, const Eigen::Vector3d& q, const Eigen::Vector3d& f,
                     const Eigen::Vector3d& tip, const Eigen::Vector3d& axis, double bound) {
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = -bound, hi = bound;
  double t1 = hi - ratio * (hi - lo), t2 = lo + ratio * (hi - lo);
  double d1 = SignedDistanceToTorus(cutter, q - t1 * f, tip, axis);
  double d2 = SignedDistanceToTorus(cutter, q - t2 * f, tip, axis);
  while (hi - lo > 1e-7) {
    if (d1 < d2) {
      hi = t2, t2 = t1, d2 = d1;
      t1 = hi - ratio * (hi - lo);
      d1 = SignedDistanceToTorus(cutter, q - t1 * f, tip, axis);
    } else {
      lo = t1, t1 = t2, d1 = d2;
      t2 = lo + ratio * (hi - lo);
      d2 = SignedDistanceToTorus(cutter, q - t2 * f, tip, axis);
    }
  }
  return std::min(d1, d2);
}

// Where the deviation crosses the tolerance between samples `in` and `out`.
double CrossingS(const CrossSection& section, const std::vector<double>& deviation,
                 double tolerance_mm, int in, int out) {
  const double fraction = (tolerance_mm - deviation[in]) / (deviation[out] - deviation[in]);
  return section.s(in) + fraction * (section.s(out) - section.s(in));
}

// The far end of the strip from `start` in `direction`; sets *truncated
// when it runs out of valid samples.
double StripEnd(const CrossSection& section, const std::vector<double>& deviation,
                double tolerance_mm, int start, int direction, bool* truncated) {
  int k = start;
  const int size = static_cast<int>(deviation.size());
  while (true) {
    const int next = k + direction;
    if (next < 0 || next >= size || !section.valid[next]) {
      *truncated = true;
      return section.s(k);
    }
    if (deviation[next] > tolerance_mm) {
      return CrossingS(section, deviation, tolerance_mm, k, next);
    }
    k = next;
  }
}

}  // namespace

Status BuildCrossSection(const ParametricSurface& surface, double u0, double v0,
                         const Eigen::Vector3d& feed_hint, double half_width_mm,
                         int samples_per_side, CrossSection* section) {
  const SurfaceDerivatives at = surface.Evaluate(u0, v0);
  std::ostringstream where;
  where << "surface point (u, v) = (" << u0 << ", " << v0 << ")";
  if (at.su.cross(at.sv).norm() < 1e-12) {
    return Status::Error(where.str() + " is degenerate (su x sv = 0)");
  }
  CrossSection& c = *section;
  c.cc = at.p;
  c.n = surface.ToolSideNormal(at);
  const Eigen::Vector3d tangent = feed_hint - feed_hint.dot(c.n) * c.n;
  if (tangent.norm() < 1e-9 * std::max(1.0, feed_hint.norm())) {
    return Status::Error(where.str() + ": the feed direction is normal to the surface");
  }
  c.f = tangent.normalized();
  c.b = c.n.cross(c.f);
  c.step_mm = half_width_mm / samples_per_side;
  c.centre = samples_per_side;
  const int size = 2 * samples_per_side + 1;
  c.points.assign(size, Eigen::Vector3d::Zero());
  c.normals.assign(size, Eigen::Vector3d::Zero());
  c.valid.assign(size, false);
  c.points[c.centre] = c.cc;
  c.normals[c.centre] = c.n;
  c.valid[c.centre] = true;
  MarchSide(surface, u0, v0, +1, samples_per_side, section);
  MarchSide(surface, u0, v0, -1, samples_per_side, section);
  return Status::Ok();
}

std::vector<double> CrossSectionDeviation(const TorusCutter& cutter, const CrossSection& section,
                                          const Eigen::Vector3d& tip,
                                          const Eigen::Vector3d& axis) {
  // Beyond 2R from the CC point along f no part of a cutter touching near
  // the CC point can be the nearest.
  const double bound = 2.0 * cutter.radius_mm + section.step_mm * section.centre;
  std::vector<double> deviation(section.points.size(), kInfinity);
  for (size_t k = 0; k < deviation.size(); ++k) {
    if (!section.valid[k]) continue;
    deviation[k] = SweptDistance(cutter, section.points[k], section.f, tip, axis, bound);
  }
  return deviation;
}

Strip StripFromDeviation(const CrossSection& section, const std::vector<double>& deviation,
                         double tolerance_mm) {
  Strip strip;
  int start = section.centre;
  if (!(deviation[start] <= tolerance_mm)) {
    for (size_t k = 0; k < deviation.size(); ++k) {
      if (deviation[k] < deviation[start]) start = static_cast<int>(k);
    }
  }
  strip.min_deviation = kInfinity;
  for (double d : deviation) strip.min_deviation = std::min(strip.min_deviation, d);
  if (!(deviation[start] <= tolerance_mm)) {
    // Nowhere within tolerance: an empty strip at the closest sample.
    strip.s_minus = strip.s_plus = section.s(start);
    strip.max_deviation_in_strip = deviation[start];
    return strip;
  }
  strip.s_minus = StripEnd(section, deviation, tolerance_mm, start, -1, &strip.truncated);
  strip.s_plus = StripEnd(section, deviation, tolerance_mm, start, +1, &strip.truncated);
  strip.max_deviation_in_strip = -kInfinity;
  for (size_t k = 0; k < deviation.size(); ++k) {
    const double s = section.s(static_cast<int>(k));
    if (s >= strip.s_minus && s <= strip.s_plus) {
      strip.max_deviation_in_strip = std::max(strip.max_deviation_in_strip, deviation[k]);
    }
  }
  return strip;
}

double QuadraticStripWidth(double tolerance_mm, double tool_effective_radius_mm,
                           double surface_cross_curvature_per_mm) {
  const double relative_curvature =
      1.0 / tool_effective_radius_mm - surface_cross_curvature_per_mm;
  if (relative_curvature <= 0.0) return kInfinity;
  return 2.0 * std::sqrt(2.0 * tolerance_mm / relative_curvature);
}

}  // namespace tpopt
