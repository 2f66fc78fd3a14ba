// Closed-form surfaces for strip-width tests: a plane, a sphere and a
// circular cylinder over (u, v) in [0, 1]^2, with exact partials.
#ifndef TPOPT_TESTS_ANALYTIC_SURFACES_H_
#define TPOPT_TESTS_ANALYTIC_SURFACES_H_

#include <cmath>
#include <vector>

#include <glog/logging.h>

#include "model/freeform_surface.h"
#include "model/parametric_surface.h"

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

}  // namespace tpopt::testing

#endif  // TPOPT_TESTS_ANALYTIC_SURFACES_H_
