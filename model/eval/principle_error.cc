#include "model/eval/principle_error.h"

#include <cmath>

namespace tpopt {

// Eqs. (3) and (4) subtract two nearly equal lengths of order R2, which
// loses digits for a large R2 and gives inf - inf for a straight rail.
// Multiplying by the conjugate gives the same values without cancellation:
//   (3) = 4 R R2 sin^2(alpha/2) / (R + R2 + sqrt(R^2 + R2^2 + 2 R R2 cos a))
//   (4) = 4 R R2 sin^2(alpha/2) / (R2 - R + sqrt(R^2 + R2^2 - 2 R R2 cos a))
// and, dividing by R2, the straight-rail limit 2 R sin^2(alpha/2).

double PrincipleErrorConvex(double r, double r2, double alpha_rad) {
  const double s = std::sin(0.5 * alpha_rad);
  if (std::isinf(r2)) return 2.0 * r * s * s;
  const double root =
      std::sqrt(r * r + r2 * r2 + 2.0 * r * r2 * std::cos(alpha_rad));
  return 4.0 * r * r2 * s * s / (r + r2 + root);
}

double PrincipleErrorConcave(double r, double r2, double alpha_rad) {
  const double s = std::sin(0.5 * alpha_rad);
  if (std::isinf(r2)) return 2.0 * r * s * s;
  const double root =
      std::sqrt(r * r + r2 * r2 - 2.0 * r * r2 * std::cos(alpha_rad));
  return 4.0 * r * r2 * s * s / (r2 - r + root);
}

}  // namespace tpopt
