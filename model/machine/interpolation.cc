#include "model/machine/interpolation.h"

namespace tpopt {

const char* InterpolationName(Interpolation interpolation) {
  return interpolation == Interpolation::kTcp ? "tcp" : "joint";
}

bool ParseInterpolation(const std::string& name, Interpolation* out) {
  if (name == "tcp") {
    *out = Interpolation::kTcp;
  } else if (name == "joint") {
    *out = Interpolation::kJoint;
  } else {
    return false;
  }
  return true;
}

}  // namespace tpopt
