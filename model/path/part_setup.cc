#include "model/path/part_setup.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace tpopt {

bool PartSetup::IsValid(std::string* why) const {
  static const char* kNames[] = {"tx", "ty", "tz", "rx", "ry", "rz"};
  for (int k = 0; k < 6; ++k) {
    const double v = k < 3 ? translation_mm[k] : rotation_deg[k - 3];
    const double limit = k < 3 ? 1e6 : 360.0;
    if (!(std::isfinite(v) && std::abs(v) <= limit)) {
      if (why != nullptr) {
        std::ostringstream err;
        err << "part setup " << kNames[k] << " = " << v << (k < 3 ? " mm" : " deg")
            << " must be finite and within +-" << limit;
        *why = err.str();
      }
      return false;
    }
  }
  return true;
}

Eigen::Matrix3d PartSetup::Rotation() const {
  const Eigen::Vector3d r = rotation_deg * (M_PI / 180.0);
  return (Eigen::AngleAxisd(r.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(r.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(r.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Status ParsePartSetup(const std::string& text, PartSetup* setup) {
  const std::string usage =
      "--part_setup=" + text + " must be tx,ty,tz,rx,ry,rz (mm, deg), e.g. 120,0,-35,0,0,90";
  double v[6];
  const char* at = text.c_str();
  for (int k = 0; k < 6; ++k) {
    char* end = nullptr;
    v[k] = std::strtod(at, &end);
    if (end == at || *end != (k < 5 ? ',' : '\0')) return Status::Error(usage);
    at = end + 1;
  }
  PartSetup parsed;
  parsed.translation_mm = Eigen::Vector3d(v[0], v[1], v[2]);
  parsed.rotation_deg = Eigen::Vector3d(v[3], v[4], v[5]);
  std::string why;
  if (!parsed.IsValid(&why)) return Status::Error("--part_setup: " + why);
  *setup = parsed;
  return Status::Ok();
}

void PlacePart(const PartSetup& setup, ToolPath* path) {
  const Eigen::Matrix3d r = setup.Rotation();
  for (ToolPose& p : path->poses) {
    p.p_w_tip = r * p.p_w_tip + setup.translation_mm;
    p.a_w = r * p.a_w;
  }
}

void UnplacePart(const PartSetup& setup, ToolPath* path) {
  const Eigen::Matrix3d r_t = setup.Rotation().transpose();
  for (ToolPose& p : path->poses) {
    p.p_w_tip = r_t * (p.p_w_tip - setup.translation_mm);
    p.a_w = r_t * p.a_w;
  }
}

Eigen::Vector3d UnplacePoint(const PartSetup& setup, const Eigen::Vector3d& p_w) {
  return setup.Rotation().transpose() * (p_w - setup.translation_mm);
}

}  // namespace tpopt
