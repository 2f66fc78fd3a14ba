// The seed's principle (geometric) error of flank milling a non-developable
// ruled surface with a cylinder (000 paper, section 2, eqs. 3-4).
//
// Project everything onto the normal plane of the ruling P1P2. The cutter,
// offset by R along the unit normal e_n1 at P1, is a circle of radius R
// through P1 = P2 (projected) with centre O_t = P + R e_n1. Rail C2 near P2 is
// its circle of curvature, radius R2, whose normal e_n2 makes the angle alpha
// with e_n1. The largest error lies where the line O2 O_t meets C2:
//   convex (O2 on the far side from the cutter):
//     E_max = R + R2 - sqrt(R^2 + R2^2 + 2 R R2 cos(alpha))      (3)
//   concave (O2 on the cutter's side, R2 > R):
//     E_max = R - R2 + sqrt(R^2 + R2^2 - 2 R R2 cos(alpha))      (4)
// both the depth by which the cutter circle crosses C2 (an overcut), zero at
// alpha = 0. The paper prints the convex sentence twice, once before eq. (2)
// (E_max = R - d_min) and again before eq. (3); the second is the one that
// belongs to (3), and (4) is the concave case.
#ifndef TPOPT_MODEL_PRINCIPLE_ERROR_H_
#define TPOPT_MODEL_PRINCIPLE_ERROR_H_

namespace tpopt {

// Eq. (3). R, R2 in mm (> 0), alpha in radians. Result in mm.
double PrincipleErrorConvex(double cutter_radius_mm, double rail_radius_mm, double alpha_rad);

// Eq. (4). Precondition R2 > R (the cutter fits inside the concave rail).
double PrincipleErrorConcave(double cutter_radius_mm, double rail_radius_mm, double alpha_rad);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PRINCIPLE_ERROR_H_
