// The seed's principle (geometric) error of flank milling a non-developable
// ruled surface with a cylinder (000 paper, section 2, eqs. 2-4).
//
// Geometry. P1 on rail C1 and P2 on rail C2 are the ends of one ruling; the
// cylinder of radius R is placed with its axis parallel to P1P2 and offset
// by R along the unit surface normal e_n1 at P1, so the whole ruling P1P2
// lies on the cylinder (zero error on it). Project everything onto the
// normal plane of P1P2: P1 and P2 coincide at P, the cutter becomes the
// circle of radius R about O_t = P + R e_n1, and rail C2 near P2 is replaced
// by its circle of curvature, radius R2 (mm), centre O2, tangent at P to
// the projected rail. alpha is the angle between the unit normals e_n1 at
// P1 and e_n2 at P2; the twist of a non-developable surface makes it
// non-zero, and the cutter circle then crosses C2's circle near P. The
// deepest crossing (an overcut) lies where the line O2 O_t meets C2:
//   E_max = R - d_min, d_min the distance from O_t to C2          (2)
//   convex (O2 = P - R2 e_n2, away from the cutter):
//     E_max = R + R2 - sqrt(R^2 + R2^2 + 2 R R2 cos(alpha))        (3)
//   concave (O2 = P + R2 e_n2, on the cutter's side, R2 > R):
//     E_max = R - R2 + sqrt(R^2 + R2^2 - 2 R R2 cos(alpha))        (4)
// Both vanish at alpha = 0 and tend to R (1 - cos(alpha)) as R2 -> infinity
// (a straight rail, e.g. a hyperbolic paraboloid).
//
// Note on the seed's text: the sentence "when the machined surface is convex
// the maximum error E_max is" is printed twice, once before eq. (2) and
// again before eq. (3). Before (2) it contradicts the figure and the next
// paragraph ("whether convex or concave"): E_max = R - d_min holds for both
// cases, with d_min = |O_t O2| - R2 (convex) or R2 - |O_t O2| (concave),
// which give (3) and (4). The same paragraph also calls C2 a generatrix
// (母线) where it means the rail (导线).
#ifndef TPOPT_MODEL_PRINCIPLE_ERROR_H_
#define TPOPT_MODEL_PRINCIPLE_ERROR_H_

namespace tpopt {

// Eq. (3), convex rail C2. cutter_radius_mm = R > 0, rail_radius_mm = R2 > 0
// (+infinity for a straight rail, as BSplineCurve::CurvatureRadius returns),
// alpha_rad in [0, pi). Result in mm, >= 0: the depth of the overcut.
double PrincipleErrorConvex(double cutter_radius_mm, double rail_radius_mm,
                            double alpha_rad);

// Eq. (4), concave rail C2. Preconditions as above and R2 > R (the cutter
// fits inside the concave rail). Result in mm, >= 0.
double PrincipleErrorConcave(double cutter_radius_mm, double rail_radius_mm,
                             double alpha_rad);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PRINCIPLE_ERROR_H_
