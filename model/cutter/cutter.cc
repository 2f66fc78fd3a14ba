#include "model/cutter/cutter.h"

#include <sstream>

namespace tpopt {

bool Cutter::IsValid(std::string* why) const {
  std::ostringstream err;
  if (!(std::isfinite(radius_mm) && radius_mm > 0.0)) {
    err << "cutter radius " << radius_mm << " mm must be finite and > 0";
  } else if (!(std::isfinite(flute_length_mm) && flute_length_mm > 0.0)) {
    err << "cutter flute length " << flute_length_mm
        << " mm must be finite and > 0";
  } else if (!(taper_rad >= 0.0 && taper_rad < M_PI / 4)) {
    err << "cutter taper " << taper_rad * 180.0 / M_PI
        << " deg must be in [0, 45)";
  } else {
    return true;
  }
  if (why != nullptr) *why = err.str();
  return false;
}

Status Cutter::Validate(const std::string& what) const {
  std::string why;
  if (IsValid(&why)) return Status::Ok();
  return Status::Error(what + ": " + why);
}

}  // namespace tpopt
