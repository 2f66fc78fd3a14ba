// Unit conversions shared by the whole project. Files hold mm and degrees;
// the code works in mm and radians (docs/ARCHITECTURE.md, "Units").
#ifndef TPOPT_MODEL_UNITS_H_
#define TPOPT_MODEL_UNITS_H_

#include <cmath>

namespace tpopt {

// Degrees per radian and radians per degree. Multiply by kRadToDeg to print
// an angle in degrees, by kDegToRad to read one.
constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kDegToRad = M_PI / 180.0;

// Millimetres per inch (exact by definition).
constexpr double kMmPerInch = 25.4;

}  // namespace tpopt

#endif  // TPOPT_MODEL_UNITS_H_
