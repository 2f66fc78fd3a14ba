// Local cubic B-spline fitting of cutter-location (CL) points with
// approximate arc-length parameters (seed 004, Meng).
//
// Four consecutive CL points P0..P3 with unit tangents T0..T3 give one
// cubic B-spline with six control points d0..d5 on the normalised knot
// vector U = [0,0,0,0,a,b,1,1,1,1], where a and b are the parameters of P1
// and P2. The system is
//   d0 = P0, d5 = P3                       (clamped ends)
//   C(a) = P1, C(b) = P2                   (interpolation, seed eq. (10))
//   C'(0) = 3 (d1 - d0) / a      = (S0 / a) T0
//   C'(1) = 3 (d5 - d4) / (1 - b) = (S2 / (1 - b)) T3
// S0 and S2 are the estimated arc lengths of the first and last chords. With
// the seed's approximate-arc parameters a = S0 / (S0 + S1 + S2), so the
// end speed S0 / a is the total length: the curve is near arc-length
// parametrised at its ends, which is the seed's reason for the tangent
// lengths. For the other parametrisations the same rule ("estimated arc
// length over parameter interval") keeps d1 = P0 + S0/3 T0 and
// d4 = P3 - S2/3 T3, so a comparison varies the knots only.
//
// Of the three spans only the middle one, between P1 and P2, is kept
// ("remove both sides, keep the middle"). The tangents at P1 and P2 are not
// conditions of the system, so kept spans of consecutive windows meet with
// position continuity only; their tangent mismatch is measured, not assumed
// (benchmarks/parametrization_benchmark.cc).
//
// The seed's eqs. (7)-(8) are lost in the text we have; they are the
// circle through the two points whose sagitta (chord height) is delta:
//   R = L^2 / (8 delta) + delta / 2,   S = 2 R asin(L / (2 R)).
// We evaluate them as theta = 2 atan(2 delta / L), S = L theta / sin theta,
// which is the same arc and stays finite when delta > L / 2 (more than a
// half circle, where asin would need its other branch).
#ifndef TPOPT_SOLVER_BSPLINE_FIT_H_
#define TPOPT_SOLVER_BSPLINE_FIT_H_

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "model/base/status.h"

namespace tpopt {

// How the knots a, b of a window follow from its three chords.
enum class Parametrization {
  kUniform,      // equal intervals
  kChordLength,  // proportional to chord length L
  kCentripetal,  // proportional to sqrt(L) (Lee 1989)
  kApproximateArc,  // proportional to the arc of chord height delta (seed)
};

// Where the chord height delta of the approximate arc comes from.
enum class ChordHeight {
  // One fixed delta for every chord: the seed's "chord height = the CL
  // path's machining accuracy". It does not depend on the data, so it only
  // approximates the true arc when delta matches the path's real sagitta.
  kFixed,
  // The sagitta of the circle through each chord and its neighbour point
  // in the window (our variant, compared in the README's table).
  kFromNeighbours,
};

struct LocalFitOptions {
  Parametrization parametrization = Parametrization::kApproximateArc;
  ChordHeight chord_height = ChordHeight::kFixed;
  // delta for ChordHeight::kFixed, mm. >= 0 (0 makes the arc the chord).
  double chord_height_mm = 0.001;
  bool IsValid(std::string* why) const;
};

// Length of the circular arc over a chord of `chord_mm` whose sagitta is
// `chord_height_mm` (both >= 0), mm. Equal to the chord when the height is 0.
double ApproximateArcLength(double chord_mm, double chord_height_mm);

// The arc over the chord p0 p1 whose sagitta is that of the circle through
// the chord and its neighbour point(s) (mean curvature when both are given;
// the chord itself when neither is): ChordHeight::kFromNeighbours.
double EstimatedArcLength(const Eigen::Vector3d* before, const Eigen::Vector3d& p0,
                          const Eigen::Vector3d& p1, const Eigen::Vector3d* after);

// Radius of that arc, mm: L^2 / (8 delta) + delta / 2 (+infinity at delta = 0).
double ApproximateArcRadius(double chord_mm, double chord_height_mm);

// One cubic polynomial piece in Bezier form, parameter t in [0, 1].
struct CubicSpan {
  std::array<Eigen::Vector3d, 4> bezier;
  Eigen::Vector3d Point(double t) const;
  // dC/dt, mm per unit t.
  Eigen::Vector3d Derivative(double t) const;
};

// The fitted window: control points d0..d5 and interior knots a < b.
struct WindowFit {
  std::array<Eigen::Vector3d, 6> control_points;
  double knot_a = 0.0;  // u4, the parameter of P1
  double knot_b = 0.0;  // u5, the parameter of P2
  // The three spans in Bezier form: [0, a], [a, b] (the kept one), [b, 1].
  std::array<CubicSpan, 3> Spans() const;
  // The kept middle span, from exactly P1 to exactly P2.
  CubicSpan MiddleSpan(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) const;
};

// Fits one window. Preconditions on the data are checked, not assumed: a
// chord shorter than 1e-9 mm, a non-finite point or a tangent that is not
// unit (|1 - |T|| > 1e-6) returns an error naming `first_index + k` (the
// path index of the point) and its value. Allocation-free on success.
Status FitWindow(const std::array<Eigen::Vector3d, 4>& points,
                 const std::array<Eigen::Vector3d, 4>& unit_tangents, const LocalFitOptions& options,
                 size_t first_index, WindowFit* fit);

// Fits a whole polyline of n >= 4 points: span i joins point i to i + 1
// (n - 1 spans). Interior spans are the middle spans of the windows
// (i-1, i, i+1, i+2); the first and last spans, which no window has in its
// middle, are the first span of the first window and the last span of the
// last window (the seed is silent about the path's ends). Errors name
// points by `index_offset` + their index here (their index in the path).
Status FitPolyline(const std::vector<Eigen::Vector3d>& points,
                   const std::vector<Eigen::Vector3d>& unit_tangents,
                   const LocalFitOptions& options, std::vector<CubicSpan>* spans,
                   size_t index_offset = 0);

// Unit tangents of a polyline for data that comes without them: at an
// interior point the tangent of the circle through it and its neighbours
// (exact for points on a circle or a line); at the ends, that circle's
// tangent there. Needs n >= 3 distinct consecutive points; an error names
// the index of a repeated point.
Status EstimateUnitTangents(const std::vector<Eigen::Vector3d>& points,
                            std::vector<Eigen::Vector3d>* unit_tangents);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_BSPLINE_FIT_H_
