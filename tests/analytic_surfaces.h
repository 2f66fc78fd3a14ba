// Closed-form surfaces for strip-width tests: a plane, a sphere and a
// circular cylinder over (u, v) in [0, 1]^2, with exact partials; and ruled
// surfaces the shared data do not have (a strongly twisted blade, a
// helicoid strip) for the high-accuracy mode.
#ifndef TPOPT_TESTS_ANALYTIC_SURFACES_H_
#define TPOPT_TESTS_ANALYTIC_SURFACES_H_

#include <cmath>
#include <string>
#include <vector>

#include <glog/logging.h>

#include "model/geometry/freeform_surface.h"
#include "model/geometry/parametric_surface.h"
#include "model/geometry/ruled_surface.h"

namespace tpopt::testing {

// The plane z = 0 over [-L/2, L/2]^2; the cutter above it (+z).
class PlaneSurface : public ParametricSurface {
 public:
  explicit PlaneSurface(double size_mm) : size_(size_mm) {}
  SurfaceDerivatives Evaluate(double u, double v) const override {
    SurfaceDerivatives d;
    d.p = Eigen::Vector3d((u - 0.5) * size_, (v - 0.5) * size_, 0.0);
    d.su = Eigen::Vector3d(size_, 0, 0);
    d.sv = Eigen::Vector3d(0, size_, 0);
    d.suu = d.suv = d.svv = Eigen::Vector3d::Zero();
    return d;
  }
  double cutter_side_sign() const override { return 1.0; }

 private:
  double size_;
};

// A sphere of radius rho about the origin, longitude phi = (u - 0.5) span
// and latitude theta = (v - 0.5) span (radians); (0.5, 0.5) is (rho, 0, 0).
// outside = true puts the cutter outside (convex), false inside (concave).
class SphereSurface : public ParametricSurface {
 public:
  SphereSurface(double rho_mm, double span_rad, bool outside)
      : rho_(rho_mm), span_(span_rad), outside_(outside) {}
  SurfaceDerivatives Evaluate(double u, double v) const override {
    const double phi = (u - 0.5) * span_, theta = (v - 0.5) * span_;
    const double cp = std::cos(phi), sp = std::sin(phi), ct = std::cos(theta),
                 st = std::sin(theta);
    const double k = span_, r = rho_;
    SurfaceDerivatives d;
    d.p = r * Eigen::Vector3d(ct * cp, ct * sp, st);
    d.su = r * k * Eigen::Vector3d(-ct * sp, ct * cp, 0);
    d.sv = r * k * Eigen::Vector3d(-st * cp, -st * sp, ct);
    d.suu = r * k * k * Eigen::Vector3d(-ct * cp, -ct * sp, 0);
    d.suv = r * k * k * Eigen::Vector3d(st * sp, -st * cp, 0);
    d.svv = r * k * k * Eigen::Vector3d(-ct * cp, -ct * sp, -st);
    return d;
  }
  // su x sv points outwards.
  double cutter_side_sign() const override { return outside_ ? 1.0 : -1.0; }

 private:
  double rho_, span_;
  bool outside_;
};

// A cylinder of radius rho about the z axis: phi = (u - 0.5) span, z =
// (v - 0.5) length; (0.5, 0.5) is (rho, 0, 0).
class CylinderSurface : public ParametricSurface {
 public:
  CylinderSurface(double rho_mm, double span_rad, double length_mm, bool outside)
      : rho_(rho_mm), span_(span_rad), length_(length_mm), outside_(outside) {}
  SurfaceDerivatives Evaluate(double u, double v) const override {
    const double phi = (u - 0.5) * span_;
    const double c = std::cos(phi), s = std::sin(phi), k = span_, r = rho_;
    SurfaceDerivatives d;
    d.p = Eigen::Vector3d(r * c, r * s, (v - 0.5) * length_);
    d.su = r * k * Eigen::Vector3d(-s, c, 0);
    d.sv = Eigen::Vector3d(0, 0, length_);
    d.suu = r * k * k * Eigen::Vector3d(-c, -s, 0);
    d.suv = d.svv = Eigen::Vector3d::Zero();
    return d;
  }
  // su x sv points outwards.
  double cutter_side_sign() const override { return outside_ ? 1.0 : -1.0; }

 private:
  double rho_, span_, length_;
  bool outside_;
};

// The saddle z = k (x^2 - y^2) over [-L, L]^2 as an exact bicubic
// B-spline on the clamped knot vector `knots` (on [0, 1], used in both
// directions), x = -L + 2 L u and y = -L + 2 L v. Exact because a
// polynomial of degree <= 3 is its own spline: control point i is the
// blossom of the polynomial at knots i+1, i+2, i+3 (de Boor). The cutter
// is on +z.
inline FreeformSurface MakeSaddle(double k, double half_size_mm, const std::vector<double>& knots) {
  const int count = static_cast<int>(knots.size()) - 4;
  auto coordinate = [&](double t) { return -half_size_mm + 2 * half_size_mm * t; };
  std::vector<double> linear(count), square(count);
  for (int i = 0; i < count; ++i) {
    const double a = coordinate(knots[i + 1]), b = coordinate(knots[i + 2]),
                 c = coordinate(knots[i + 3]);
    linear[i] = (a + b + c) / 3;
    square[i] = (a * b + a * c + b * c) / 3;
  }
  std::vector<std::vector<Eigen::Vector3d>> net(count, std::vector<Eigen::Vector3d>(count));
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < count; ++j) {
      net[i][j] = Eigen::Vector3d(linear[i], linear[j], k * (square[i] - square[j]));
    }
  }
  FreeformSurface surface;
  const Status s = FreeformSurface::Create("saddle", knots, knots, net, 1.0, "saddle", &surface);
  CHECK(s.ok()) << s.message();
  return surface;
}

// One straight ruling: its foot on rail 0, unit direction, length.
struct Ruling {
  Eigen::Vector3d foot_w, direction_w;
  double length_mm;
};

// A ruled surface through the rulings `ruling(t)`, t in [0, 1]: both rails
// are cubic B-splines on `spans` uniform spans whose control points are the
// feet and far ends of the rulings at the Greville abscissae, so each
// control-point pair spans one closed-form ruling (the surface's rulings
// between them are blends).
template <typename RulingAt>
RuledSurface RuledThrough(const std::string& name, int spans, CutterSide side, RulingAt ruling) {
  constexpr int kDegree = 3;
  std::vector<double> knots(kDegree, 0.0);
  for (int k = 0; k <= spans; ++k) knots.push_back(static_cast<double>(k) / spans);
  knots.insert(knots.end(), kDegree, 1.0);
  std::vector<Eigen::Vector3d> feet, ends;
  for (int i = 0; i < spans + kDegree; ++i) {
    const double greville = (knots[i + 1] + knots[i + 2] + knots[i + 3]) / kDegree;
    const Ruling r = ruling(greville);
    feet.push_back(r.foot_w);
    ends.push_back(r.foot_w + r.length_mm * r.direction_w);
  }
  BSplineCurve rail0, rail1;
  CHECK(BSplineCurve::Create(kDegree, knots, feet, name + " rail 0", &rail0).ok());
  CHECK(BSplineCurve::Create(kDegree, knots, ends, name + " rail 1", &rail1).ok());
  return RuledSurface(name, rail0, rail1, side);
}

// A strongly twisted impeller blade (issue 16, item 2): the hub (rail 0) is
// an arc of radius 40 mm about the z axis over psi in [-30, 30] deg, through
// the origin at psi = 0; the 25 mm ruling leans from +z towards the outward
// radial direction n(psi) by lambda = 45 deg + twist (u - 1/2), i.e. it
// turns about the hub's tangent by `twist_deg` end to end (non-developable:
// the turn is about the rail itself). Polar angles 45 -/+ twist/2 deg.
inline RuledSurface TwistedBlade(double twist_deg) {
  const double twist = twist_deg * M_PI / 180;
  return RuledThrough("twisted blade", 10, CutterSide::kPositive, [&](double u) {
    const double psi = (u - 0.5) * M_PI / 3, lambda = M_PI / 4 + twist * (u - 0.5);
    const Eigen::Vector3d radial(std::sin(psi), std::cos(psi), 0.0);
    return Ruling{40.0 * radial - Eigen::Vector3d(0, 40, 0),
                  std::cos(lambda) * Eigen::Vector3d::UnitZ() + std::sin(lambda) * radial, 25.0};
  });
}

// A helicoid strip (issue 16, item 2): rulings through the x axis and normal
// to it, at height x = 60 (u - 1/2) mm pointing along (0, sin theta,
// cos theta), theta = 45 deg + twist (u - 1/2), between 8 and 33 mm from
// the axis. The rails are helices (on their control points).
inline RuledSurface HelicoidStrip(double twist_deg) {
  const double twist = twist_deg * M_PI / 180;
  return RuledThrough("helicoid strip", 10, CutterSide::kPositive, [&](double u) {
    const double theta = M_PI / 4 + twist * (u - 0.5);
    const Eigen::Vector3d direction(0.0, std::sin(theta), std::cos(theta));
    return Ruling{Eigen::Vector3d(60.0 * (u - 0.5), 0, 0) + 8.0 * direction, direction, 25.0};
  });
}

}  // namespace tpopt::testing

#endif  // TPOPT_TESTS_ANALYTIC_SURFACES_H_
