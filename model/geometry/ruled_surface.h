// Ruled surface r(u, v) = (1 - v) C1(u) + v C2(u), u, v in [0, 1].
//
// C1 is rail 0 (where the tool tip runs), C2 rail 1. The normal is
// N = r_u x r_v, flipped so that it points to the side the cutter lies on
// (docs/ARCHITECTURE.md, "Ruled surface").
#ifndef TPOPT_MODEL_RULED_SURFACE_H_
#define TPOPT_MODEL_RULED_SURFACE_H_

#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "model/geometry/bspline_curve.h"

namespace tpopt {

enum class CutterSide { kPositive, kNegative };

class RuledSurface {
 public:
  RuledSurface() = default;
  RuledSurface(std::string name, BSplineCurve rail0, BSplineCurve rail1,
               CutterSide side)
      : name_(std::move(name)),
        rail0_(std::move(rail0)),
        rail1_(std::move(rail1)),
        side_(side) {}

  const std::string& name() const { return name_; }
  const BSplineCurve& rail(int i) const { return i == 0 ? rail0_ : rail1_; }
  CutterSide cutter_side() const { return side_; }
  // +1 for kPositive, -1 for kNegative.
  double side_sign() const { return side_ == CutterSide::kPositive ? 1 : -1; }

  // The ruling at u, from C1(u) (v = 0) to C2(u) (v = 1): many points of
  // one ruling for two rail evaluations in all.
  struct Ruling {
    Eigen::Vector3d c1, c2;
    Eigen::Vector3d Point(double v) const { return (1.0 - v) * c1 + v * c2; }
  };
  Ruling RulingAt(double u) const { return {rail0_.Point(u), rail1_.Point(u)}; }

  // Point in W, mm.
  Eigen::Vector3d Point(double u, double v) const { return RulingAt(u).Point(v); }
  // Partial derivatives, mm per unit parameter.
  Eigen::Vector3d Du(double u, double v) const;
  Eigen::Vector3d Dv(double u) const;
  // Unit normal on the cutter's side. Precondition: r_u x r_v != 0.
  Eigen::Vector3d Normal(double u, double v) const;
  // Gaussian curvature K = (LN - M^2) / (EG - F^2), 1/mm^2. For a ruled
  // surface r_vv = 0, so K = -M^2 / (EG - F^2) <= 0; zero exactly when the
  // surface is developable along the ruling.
  double GaussianCurvature(double u, double v) const;
  // Radius of curvature of rail `i` at u, mm: the R_2 of the seed's
  // principle-error formula (000 paper, eqs. 3-4) when i = 1.
  double RailCurvatureRadius(int i, double u) const {
    return rail(i).CurvatureRadius(u);
  }

 private:
  std::string name_;
  BSplineCurve rail0_, rail1_;
  CutterSide side_ = CutterSide::kPositive;
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_RULED_SURFACE_H_
