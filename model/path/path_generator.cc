#include "model/path/path_generator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include <glog/logging.h>

#include "model/base/invalid_field.h"

namespace tpopt {
namespace {

// Unit normal on the cutter side of the (possibly distorted) ruling from
// p1 to p2 with rail tangent t at its end; false if degenerate.
bool RulingNormal(const RuledSurface& surface, const Eigen::Vector3d& tangent,
                  const Eigen::Vector3d& ruling, Eigen::Vector3d* n) {
  const Eigen::Vector3d cross = tangent.cross(ruling);
  const double len = cross.norm();
  if (!(len > 1e-12 * tangent.norm() * ruling.norm()) || !(len > 0)) return false;
  *n = surface.side_sign() * cross / len;
  return true;
}

// Tilts `axis` by a normally distributed angle about a random normal.
Eigen::Vector3d Perturb(const Eigen::Vector3d& axis, double sigma_rad, std::mt19937* rng) {
  std::normal_distribution<double> tilt(0.0, sigma_rad);
  std::uniform_real_distribution<double> turn(0.0, 2.0 * M_PI);
  const Eigen::Vector3d e1 = axis.unitOrthogonal();
  const Eigen::Vector3d e2 = axis.cross(e1);
  const double phi = turn(*rng);
  const Eigen::Vector3d about = std::cos(phi) * e1 + std::sin(phi) * e2;
  return Eigen::AngleAxisd(tilt(*rng), about) * axis;
}

}  // namespace

bool FlankPathOptions::IsValid(std::string* why) const {
  FirstInvalid check;
  check.Require(std::isfinite(cutter_radius_mm) && cutter_radius_mm > 0,
          InvalidField("--cutter_radius", cutter_radius_mm, "finite and > 0 mm"));
  check.Require(poses >= 2, InvalidField("--poses", poses, ">= 2"));
  check.Require(std::isfinite(feed_mm_per_min) && feed_mm_per_min > 0,
          InvalidField("--feed", feed_mm_per_min, "finite and > 0 mm/min"));
  check.Require(std::isfinite(uv_distortion) && std::abs(uv_distortion) <= 0.5,
          InvalidField("--uv_distortion", uv_distortion, "finite and within [-0.5, 0.5]"));
  check.Require(distortion_width > 0 && distortion_width <= 1,
          InvalidField("--distortion_width", distortion_width, "in (0, 1]"));
  check.Require(distortion_center >= 0 && distortion_center <= 1,
          InvalidField("--distortion_center", distortion_center, "in [0, 1]"));
  check.Require(std::isfinite(axis_noise_deg) && axis_noise_deg >= 0 && axis_noise_deg < 45,
          InvalidField("--axis_noise_deg", axis_noise_deg, "in [0, 45)"));
  check.Require(std::isfinite(flute_length_mm) && flute_length_mm >= 0,
          InvalidField("--flute_length", flute_length_mm, "finite and >= 0 mm"));
  check.Require(taper_rad >= 0 && taper_rad < M_PI / 4,
          InvalidField("taper_rad", taper_rad, "in [0, pi/4)"));
  return check.Report(why);
}

double UvDistortion(const FlankPathOptions& o, double u) {
  const double x = (u - o.distortion_center) / o.distortion_width;
  if (std::abs(x) >= 0.5) return 0.0;
  const double c = std::cos(M_PI * x);
  return o.uv_distortion * c * c;
}

Status FlankPoseAt(const RuledSurface& surface, const FlankPathOptions& o, double u,
                   ToolPose* pose_out, double* ruling_mm) {
  CHECK(pose_out != nullptr);
  const double r = o.cutter_radius_mm;
  const double u2 = std::clamp(u + UvDistortion(o, u), 0.0, 1.0);
  const auto c1 = surface.rail(0).Evaluate(u, 1);
  const auto c2 = surface.rail(1).Evaluate(u2, 1);
  const Eigen::Vector3d ruling = c2[0] - c1[0];
  if (ruling_mm != nullptr) *ruling_mm = ruling.norm();
  Eigen::Vector3d n1, n2;
  // The CAM's normals come from its own (possibly distorted) pairing.
  if (!RulingNormal(surface, c1[1], ruling, &n1) || !RulingNormal(surface, c2[1], ruling, &n2)) {
    std::ostringstream err;
    err << surface.name() << ": the surface normal vanishes at u = " << u;
    return Status::Error(err.str());
  }
  ToolPose pose;
  pose.feed_mm_per_min = o.feed_mm_per_min;
  pose.p_w_tip = c1[0] + r * n1;
  const double taper = o.taper_rad;
  if (o.strategy == FlankStrategy::kSinglePointOffset) {
    const Eigen::Vector3d e = ruling.normalized();
    // n1 is normal to e, so the cone's generator a - tan(taper) n_perp,
    // n_perp = cos(taper) n1 - sin(taper) e, is parallel to e.
    pose.a_w = std::cos(taper) * e + std::sin(taper) * n1;
    pose.p_w_tip = c1[0] + r * (std::cos(taper) * n1 - std::sin(taper) * e);
  } else {
    pose.a_w = (c2[0] + r * n2 - pose.p_w_tip).normalized();
    // A cone: C1 at the tip's radius and C2 at the radius of its own
    // height, both along the normals made orthogonal to the axis; a
    // fixed point in the axis, which moves by O(taper^2) each round.
    for (int round = 0; taper > 0 && round < 8; ++round) {
      const Eigen::Vector3d a = pose.a_w;
      const Eigen::Vector3d n1p = (n1 - n1.dot(a) * a).normalized();
      const Eigen::Vector3d n2p = (n2 - n2.dot(a) * a).normalized();
      pose.p_w_tip = c1[0] + r * n1p;
      const double height = (c2[0] - pose.p_w_tip).dot(a);
      const Eigen::Vector3d top = c2[0] + (r + height * std::tan(taper)) * n2p;
      pose.a_w = (top - pose.p_w_tip).normalized();
    }
  }
  *pose_out = pose;
  return Status::Ok();
}

Status GenerateFlankPath(const RuledSurface& surface, const FlankPathOptions& o,
                         ToolPath* path) {
  CHECK(path != nullptr);
  std::string why;
  if (!o.IsValid(&why)) return Status::Error("generate: " + why);
  const double r = o.cutter_radius_mm;
  std::mt19937 rng(o.noise_seed);
  ToolPath out;
  double longest_ruling_mm = 0.0;
  for (int i = 0; i < o.poses; ++i) {
    const double u = static_cast<double>(i) / (o.poses - 1);
    ToolPose pose;
    double ruling_mm = 0.0;
    RETURN_IF_ERROR(FlankPoseAt(surface, o, u, &pose, &ruling_mm));
    longest_ruling_mm = std::max(longest_ruling_mm, ruling_mm);
    if (o.axis_noise_deg > 0) pose.a_w = Perturb(pose.a_w, o.axis_noise_deg * M_PI / 180, &rng);
    out.poses.push_back(pose);
  }
  Cutter cutter;
  cutter.radius_mm = r;
  cutter.flute_length_mm = o.flute_length_mm > 0 ? o.flute_length_mm : 1.25 * longest_ruling_mm;
  cutter.taper_rad = o.taper_rad;
  out.cutter = cutter;
  std::ostringstream title;
  title << "tpopt generate: " << surface.name() << ", "
        << (o.strategy == FlankStrategy::kSinglePointOffset ? "SPO" : "DPO") << ", R " << r
        << " mm, " << o.poses << " poses, uv distortion " << o.uv_distortion << ", axis noise "
        << o.axis_noise_deg << " deg (seed " << o.noise_seed << ")";
  out.title = title.str();
  *path = std::move(out);
  return Status::Ok();
}

ToolPath RepeatedPasses(const ToolPath& pass, int passes) {
  ToolPath out = WithoutPoses(pass);
  out.poses.reserve(pass.poses.size() * static_cast<size_t>(std::max(passes, 0)));
  for (int k = 0; k < passes; ++k) {
    for (size_t i = 0; i < pass.poses.size(); ++i) {
      out.poses.push_back(pass.poses[i]);
      out.poses.back().rapid = k > 0 && i == 0;
    }
  }
  return out;
}

}  // namespace tpopt
