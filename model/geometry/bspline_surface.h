// A clamped, non-rational tensor-product B-spline surface S(u, v) in R^3,
// of degree 1 to 3 in each direction (bicubic is the common case: the
// seed-004 pencil surface, and free-form workpieces in general).
//
// Like BSplineCurve, each knot vector is mapped affinely to [0, 1], so every
// surface in tpopt is parametrised on the unit square.
#ifndef TPOPT_MODEL_BSPLINE_SURFACE_H_
#define TPOPT_MODEL_BSPLINE_SURFACE_H_

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "model/base/status.h"

namespace tpopt {

// Point and partial derivatives at one (u, v), mm per unit parameter^k.
struct SurfacePoint {
  Eigen::Vector3d point, du, dv, duu, duv, dvv;
  // Unit normal S_u x S_v / |S_u x S_v|; zero where the surface is singular
  // (|S_u x S_v| <= 1e-12 |S_u| |S_v|).
  Eigen::Vector3d UnitNormal() const;
};

class BSplineSurface {
 public:
  static constexpr int kMaxDegree = 3;

  BSplineSurface() = default;

  // Validates and builds a surface from control_points[i][j], i along u
  // (knots_u.size() - degree_u - 1 rows), j along v (all rows the same
  // length). Degrees in [1, 3]; knot vectors as BSplineCurve::Create
  // demands; control points finite. `what` starts every message (e.g.
  // "part.json").
  static Status Create(int degree_u, int degree_v, std::vector<double> knots_u,
                       std::vector<double> knots_v,
                       std::vector<std::vector<Eigen::Vector3d>> control_points,
                       const std::string& what, BSplineSurface* surface);

  int degree_u() const { return degree_u_; }
  int degree_v() const { return degree_v_; }
  int rows() const { return rows_; }  // control points along u
  int cols() const { return cols_; }  // control points along v
  const Eigen::Vector3d& control_point(int i, int j) const { return net_[i * cols_ + j]; }
  // Normalised knots.
  const std::vector<double>& knots_u() const { return knots_u_; }
  const std::vector<double>& knots_v() const { return knots_v_; }

  // Point and first and second partials at (u, v), each clamped to [0, 1].
  SurfacePoint Evaluate(double u, double v) const;
  Eigen::Vector3d Point(double u, double v) const { return Evaluate(u, v).point; }
  Eigen::Vector3d UnitNormal(double u, double v) const { return Evaluate(u, v).UnitNormal(); }

 private:
  int degree_u_ = 0, degree_v_ = 0, rows_ = 0, cols_ = 0;
  std::vector<double> knots_u_, knots_v_;
  std::vector<Eigen::Vector3d> net_;  // row-major, rows_ x cols_
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_BSPLINE_SURFACE_H_
