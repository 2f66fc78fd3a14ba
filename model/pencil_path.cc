#include "model/pencil_path.h"

#include <cmath>
#include <sstream>

#include "model/invalid_field.h"
#include "model/json_io.h"
#include "model/surface_projection.h"

namespace tpopt {
namespace {

constexpr size_t kMaxPointsPerRun = 1000000;

bool Finite(double x) { return std::isfinite(x); }

std::string Describe(const std::string& name, double value, const std::string& rule) {
  std::ostringstream out;
  out << name << " = " << value << " " << rule;
  return out.str();
}

// d(unit normal)/dm from the surface's second partials and (u', v').
Eigen::Vector3d NormalDerivative(const SurfacePoint& sp, double du_dm, double dv_dm) {
  const Eigen::Vector3d n = sp.du.cross(sp.dv);
  const Eigen::Vector3d dsu = sp.duu * du_dm + sp.duv * dv_dm;
  const Eigen::Vector3d dsv = sp.duv * du_dm + sp.dvv * dv_dm;
  const Eigen::Vector3d dn = dsu.cross(sp.dv) + sp.du.cross(dsv);
  const Eigen::Vector3d unit = n.normalized();
  return (dn - unit * unit.dot(dn)) / n.norm();
}

}  // namespace

bool GuidePlacement::IsValid(std::string* why) const {
  std::string problem;
  if (!(anchor_u >= 0 && anchor_u <= 1)) problem = Describe("anchor_u", anchor_u, "is outside [0, 1]");
  if (!(anchor_v >= 0 && anchor_v <= 1)) problem = Describe("anchor_v", anchor_v, "is outside [0, 1]");
  if (!Finite(lift_mm)) problem = Describe("lift_mm", lift_mm, "is not finite");
  if (!Finite(spin_deg)) problem = Describe("spin_deg", spin_deg, "is not finite");
  if (why) *why = problem;
  return problem.empty();
}

bool PencilOptions::IsValid(std::string* why) const {
  std::string problem;
  if (!(ball_radius_mm > 0 && Finite(ball_radius_mm))) {
    problem = InvalidField("--ball_radius", ball_radius_mm, "finite and > 0 mm");
  } else if (!(feed_mm_per_min > 0 && Finite(feed_mm_per_min))) {
    problem = InvalidField("--feed", feed_mm_per_min, "finite and > 0 mm/min");
  } else if (!(interpolation_period_s > 0 && Finite(interpolation_period_s))) {
    problem = InvalidField("--interpolation_period_ms", interpolation_period_s * 1e3,
                           "finite and > 0 ms");
  }
  if (why) *why = problem;
  return problem.empty();
}

Status PencilGeometry::Create(const BSplineSurface& surface, const GuidePlacement& placement,
                              double ball_radius_mm, PencilGeometry* geometry) {
  std::string why;
  if (!placement.IsValid(&why)) return Status::Error("placement: " + why);
  const SurfacePoint anchor = surface.Evaluate(placement.anchor_u, placement.anchor_v);
  const Eigen::Vector3d normal = anchor.UnitNormal();
  const Eigen::Vector3d x_in_plane = anchor.du - normal * normal.dot(anchor.du);
  if (normal.isZero() || !(x_in_plane.norm() > 0)) {
    std::ostringstream err;
    err << "placement: the surface is singular at the anchor (" << placement.anchor_u << ", "
        << placement.anchor_v << ")";
    return Status::Error(err.str());
  }
  const double spin = placement.spin_deg * M_PI / 180.0;
  const Eigen::Vector3d x0 = x_in_plane.normalized(), y0 = normal.cross(x0);
  geometry->surface_ = &surface;
  geometry->origin_ = anchor.point + placement.lift_mm * normal;
  geometry->x_axis_ = std::cos(spin) * x0 + std::sin(spin) * y0;
  geometry->y_axis_ = -std::sin(spin) * x0 + std::cos(spin) * y0;
  geometry->direction_ = -normal;
  geometry->ball_radius_mm_ = ball_radius_mm;
  return Status::Ok();
}

Eigen::Vector3d PencilGeometry::Place(const Eigen::Vector3d& planar) const {
  return origin_ + planar.x() * x_axis_ + planar.y() * y_axis_;
}

Status PencilGeometry::At(const BSplineCurve& guide, double m, Eigen::Vector2d* uv,
                          PencilPoint* point) const {
  const auto q = guide.Evaluate(m, 1);
  const Eigen::Vector3d placed = Place(q[0]);
  const Eigen::Vector3d dplaced_dm = q[1].x() * x_axis_ + q[1].y() * y_axis_;
  SurfaceHit hit;
  Status s = ProjectAlongDirection(*surface_, placed, direction_, uv, &hit);
  std::ostringstream where;
  where << "guide parameter m = " << m << ": ";
  if (!s.ok()) return Status::Error(where.str() + s.message());
  const SurfacePoint sp = surface_->Evaluate(hit.u, hit.v);
  Eigen::Vector3d normal = sp.UnitNormal();
  if (normal.isZero()) return Status::Error(where.str() + "the surface is singular there");
  // The ball sits on the side the guide plane is on.
  const double side = normal.dot(-direction_) >= 0 ? 1.0 : -1.0;
  normal *= side;
  // S(u(m), v(m)) - Q(m) stays parallel to O: its components across O
  // vanish, so E^T (S_u u' + S_v v') = E^T Q'(m), E spanning the plane
  // normal to O.
  const Eigen::Vector3d e1 = x_axis_, e2 = y_axis_;
  Eigen::Matrix2d jacobian;
  jacobian << sp.du.dot(e1), sp.dv.dot(e1), sp.du.dot(e2), sp.dv.dot(e2);
  if (!(std::abs(jacobian.determinant()) > 1e-12 * sp.du.norm() * sp.dv.norm())) {
    return Status::Error(where.str() + "the surface is parallel to the projection direction");
  }
  const Eigen::Vector2d duv = jacobian.inverse() * Eigen::Vector2d(dplaced_dm.dot(e1),
                                                                    dplaced_dm.dot(e2));
  point->m = m;
  point->u = hit.u;
  point->v = hit.v;
  point->cc = sp.point;
  point->dcc_dm = sp.du * duv.x() + sp.dv * duv.y();
  point->normal = normal;
  point->cl = sp.point + ball_radius_mm_ * normal;
  point->dcl_dm = point->dcc_dm + ball_radius_mm_ * side * NormalDerivative(sp, duv.x(), duv.y());
  if (uv != nullptr) *uv = Eigen::Vector2d(hit.u, hit.v);
  return Status::Ok();
}

Status GeneratePencilRuns(const PencilGeometry& geometry, const std::vector<BSplineCurve>& guides,
                          const PencilOptions& options, std::vector<PencilRun>* runs) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(why);
  const double step_mm = options.StepMm();
  runs->assign(guides.size(), PencilRun());
  for (size_t c = 0; c < guides.size(); ++c) {
    const std::string curve = "curve " + std::to_string(c) + ", ";
    std::vector<PencilPoint>& points = (*runs)[c].points;
    PencilPoint point;
    Eigen::Vector2d uv;
    Status s = geometry.At(guides[c], 0.0, nullptr, &point);
    if (!s.ok()) return Status::Error(curve + s.message());
    uv = Eigen::Vector2d(point.u, point.v);
    points.push_back(point);
    while (points.back().m < 1.0) {
      const double speed = points.back().dcc_dm.norm();
      // A stalled guide (zero speed) still advances, and no step skips
      // more than a tenth of the curve where it is slow.
      double m = points.back().m + (speed > 1e-9 ? std::min(step_mm / speed, 0.1) : 0.01);
      const bool last = m >= 1.0;
      m = std::min(m, 1.0);
      s = geometry.At(guides[c], m, &uv, &point);
      if (!s.ok()) return Status::Error(curve + s.message());
      // A last chord much shorter than a step would only add a point.
      if (last && points.size() > 1 && (point.cc - points.back().cc).norm() < 0.2 * step_mm) {
        points.back() = point;
      } else {
        points.push_back(point);
      }
      if (points.size() > kMaxPointsPerRun) {
        return Status::Error(curve + "more than 1e6 points at a step of " +
                             std::to_string(step_mm) + " mm");
      }
    }
  }
  return Status::Ok();
}

Status LoadPencilJob(const std::string& surface_path, const std::string& curve_path,
                     double ball_radius_mm, PencilJob* job) {
  Status s = ReadBSplineSurfaceJson(surface_path, &job->surface);
  return s.ok() ? CompletePencilJob(curve_path, ball_radius_mm, job) : s;
}

Status CompletePencilJob(const std::string& curve_path, double ball_radius_mm, PencilJob* job) {
  RETURN_IF_ERROR(ReadGuideCurvesJson(curve_path, &job->guides, &job->placement));
  Status s = PencilGeometry::Create(job->surface, job->placement, ball_radius_mm, &job->geometry);
  if (!s.ok()) return Status::Error(curve_path + ": " + s.message());
  return Status::Ok();
}

}  // namespace tpopt
