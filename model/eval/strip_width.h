// The machining strip of a torus cutter at one cutter-contact (CC) point.
//
// At the CC point S(u0, v0) with tool-side unit normal n and unit feed
// direction f (tangent), the cross direction is b = n x f. The surface's
// cross section is the curve where the plane through the CC point normal
// to f cuts the surface, sampled at cross offsets s (mm along b).
//
// The deviation at a cross-section point q is the distance from q to the
// cutter swept along the line through it in the feed direction f: the
// material the pass leaves there (the swept solid's silhouette seen along
// f; negative = gouge). Because the solid is convex, the distance to its
// translate by t f is convex in t, so a golden-section search finds the
// minimum. The effective cutting segment (the seed's "effective
// characteristic-curve segment") is the contiguous range [s_minus, s_plus]
// around the contact where the deviation is at most the tolerance; the
// strip width is s_plus - s_minus.
#ifndef TPOPT_MODEL_STRIP_WIDTH_H_
#define TPOPT_MODEL_STRIP_WIDTH_H_

#include <vector>

#include <Eigen/Core>

#include "model/geometry/parametric_surface.h"
#include "model/base/status.h"
#include "model/cutter/torus_cutter.h"

namespace tpopt {

struct CrossSection {
  Eigen::Vector3d cc, n, f, b;  // CC point and its unit frame (W)
  double step_mm = 0.0;         // spacing of the samples in s
  int centre = 0;               // index of s = 0
  // Sample k sits at s = (k - centre) step_mm; `valid` is false where the
  // plane leaves the surface's parameter square (or Newton failed).
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<bool> valid;
  double s(int k) const { return (k - centre) * step_mm; }
};

// Samples the cross section at (u0, v0) over |s| <= half_width_mm with
// `samples_per_side` steps each way; the feed direction is `feed_hint`
// projected onto the tangent plane. Fails (naming u0, v0) where the surface
// is degenerate (su x sv = 0) or the hint is normal to the surface.
Status BuildCrossSection(const ParametricSurface& surface, double u0, double v0,
                         const Eigen::Vector3d& feed_hint, double half_width_mm,
                         int samples_per_side, CrossSection* section);

struct Strip {
  double s_minus = 0.0, s_plus = 0.0;  // mm along b; s_minus <= s_plus
  double width() const { return s_plus - s_minus; }
  double mid() const { return 0.5 * (s_plus + s_minus); }
  // Least deviation over every valid sample (< 0: the tool gouges) and the
  // largest inside the strip, mm.
  double min_deviation = 0.0;
  double max_deviation_in_strip = 0.0;
  // True when the strip reached the end of the valid samples (the surface
  // edge or the sampled range) on either side: the width is a lower bound.
  bool truncated = false;
};

// Deviation (mm) of every sample for the cutter at (tip, axis); invalid
// samples get +infinity.
std::vector<double> CrossSectionDeviation(const TorusCutter& cutter, const CrossSection& section,
                                          const Eigen::Vector3d& tip,
                                          const Eigen::Vector3d& axis);

// The strip for the deviations of CrossSectionDeviation and a tolerance
// (mm, > 0). It grows from the CC sample (or, when that one is beyond the
// tolerance, the sample of least deviation) while the deviation stays
// within the tolerance; each end is interpolated linearly between the last
// sample in and the first out.
Strip StripFromDeviation(const CrossSection& section, const std::vector<double>& deviation,
                         double tolerance_mm);

// Closed-form strip width (mm) of the quadratic approximation: the gap
// between tool and surface across the feed grows as s^2 / (2 R_rel) with
// 1 / R_rel = 1 / R_eff_tool - k_surface (k_surface the normal curvature
// across the feed, positive when concave towards the tool), so
// w = 2 sqrt(2 h R_rel). +infinity when 1 / R_rel <= 0.
double QuadraticStripWidth(double tolerance_mm, double tool_effective_radius_mm,
                           double surface_cross_curvature_per_mm);

}  // namespace tpopt

#endif  // TPOPT_MODEL_STRIP_WIDTH_H_
