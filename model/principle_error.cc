#include "model/principle_error.h"

#include <cmath>

namespace tpopt {

double PrincipleErrorConvex(double r, double r2, double alpha_rad) {
  return r + r2 - std::sqrt(r * r + r2 * r2 + 2 * r * r2 * std::cos(alpha_rad));
}

double PrincipleErrorConcave(double r, double r2, double alpha_rad) {
  return r - r2 + std::sqrt(r * r + r2 * r2 - 2 * r * r2 * std::cos(alpha_rad));
}

}  // namespace tpopt
