#include "solver/strip/tool_posture.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "model/base/invalid_field.h"
#include "model/base/units.h"

namespace tpopt {
namespace {

// The cross-section point and normal at offset s, linear between samples,
// clamped to the valid samples around the CC point.
void ContactAt(const CrossSection& section, double s, Eigen::Vector3d* point,
               Eigen::Vector3d* normal) {
  const double x = section.centre + s / section.step_mm;
  int lo = static_cast<int>(std::floor(x));
  lo = std::clamp(lo, 0, static_cast<int>(section.points.size()) - 2);
  double fraction = std::clamp(x - lo, 0.0, 1.0);
  // Step back towards the CC point until both samples are valid.
  while (!(section.valid[lo] && section.valid[lo + 1])) {
    lo += lo < section.centre ? 1 : -1;
    fraction = lo < section.centre ? 0.0 : 1.0;
  }
  *point = (1 - fraction) * section.points[lo] + fraction * section.points[lo + 1];
  *normal = ((1 - fraction) * section.normals[lo] + fraction * section.normals[lo + 1]).normalized();
}

// How good a candidate is: any gouge-free strip beats any gouging one;
// among gouge-free strips the wider wins, among gouging ones the shallower.
struct Candidate {
  Posture posture;
  Strip strip;
  bool feasible = false;
  bool BetterThan(const Candidate& other) const {
    if (feasible != other.feasible) return feasible;
    if (feasible) return strip.width() > other.strip.width() + 1e-9;
    return strip.min_deviation > other.strip.min_deviation + 1e-12;
  }
};

// The posture with contact at s_c, evaluated.
Candidate Evaluate(const TorusCutter& cutter, const CrossSection& section, const Posture& posture,
                   const PostureOptions& options) {
  Candidate c;
  c.posture = posture;
  c.strip = EvaluatePosture(cutter, section, posture, options.tolerance_mm);
  c.feasible = c.strip.min_deviation >= -options.gouge_tolerance_mm && c.strip.width() > 0;
  return c;
}

// MPEC's positioning: move the contact along the section until the strip's
// mid-point is the CC point, by the secant method on mid(s_c) (moving the
// contact by ds moves the strip by about ds, so it starts with s_c = -mid).
// A posture whose strip cannot be centred within half a sample is not an
// MPEC posture and is marked infeasible.
Candidate CentredOnCc(const TorusCutter& cutter, const CrossSection& section, Posture posture,
                      const PostureOptions& options) {
  const double reach = 0.9 * section.step_mm * section.centre;
  const double close_enough = 0.25 * section.step_mm;
  Candidate c = Evaluate(cutter, section, posture, options);
  double previous_s = posture.contact_s_mm, previous_mid = c.strip.mid();
  double next_s = previous_s - previous_mid;
  for (int step = 0; step < 8 && std::abs(c.strip.mid()) > close_enough; ++step) {
    posture.contact_s_mm = std::clamp(next_s, -reach, reach);
    c = Evaluate(cutter, section, posture, options);
    const double slope = (c.strip.mid() - previous_mid) / (posture.contact_s_mm - previous_s);
    previous_s = posture.contact_s_mm;
    previous_mid = c.strip.mid();
    // A flat or reversed response: fall back to the unit-slope step.
    next_s = previous_s - previous_mid / (slope > 0.2 ? slope : 1.0);
  }
  if (std::abs(c.strip.mid()) > 2 * close_enough) c.feasible = false;
  return c;
}

// At a fixed tilt, the least lead that does not gouge. A smaller lead
// flattens the tool across the feed (R_eff = r + R0 / sin(lead) at zero
// tilt), which widens the strip until the surface starts to rise into the
// tool somewhere: the widest gouge-free strip at this tilt is at that
// boundary, where the tool touches the section at a further point — the
// multi-point contact. Found by bisection on the lead; on a section where
// even the least lead does not gouge (a convex one) it is the least lead.
template <typename Place>
Candidate LeadAtGougeBoundary(const PostureOptions& options, double tilt, Place place) {
  Candidate high = place(options.max_lead_rad, tilt);
  if (!high.feasible) return high;
  const Candidate low = place(options.min_lead_rad, tilt);
  if (low.feasible) return low.BetterThan(high) ? low : high;
  double infeasible = options.min_lead_rad, feasible = options.max_lead_rad;
  Candidate best = high;
  while (feasible - infeasible > options.angle_resolution_rad) {
    const double lead = 0.5 * (feasible + infeasible);
    const Candidate c = place(lead, tilt);
    if (c.feasible) {
      feasible = lead;
      if (c.BetterThan(best)) best = c;
    } else {
      infeasible = lead;
    }
  }
  return best;
}

// Widest gouge-free strip over lead and tilt: for each tilt the lead at the
// gouge boundary (above), and over the tilt a grid across the whole range
// followed by grids zooming in on the best tilt, each a third of the
// spacing of the one before. The widest strips lie on a thin ridge in
// (lead, tilt) along that boundary, and the width jumps where a further
// contact appears; a gradient method, or a search over both angles at once,
// steps over the ridge.
//
// Where two tilts give strips of nearly equal width (within
// options.continuity_tie of each other; a symmetric section has two mirror
// optima) the one nearer the previous CC point's posture is taken, so that
// the pass does not jump between them.
template <typename Place>
Candidate SearchLeadTilt(const PostureOptions& options, const Posture* previous, Place place) {
  const auto preferred = [&](const Candidate& c, const Candidate& best) {
    const double wider = std::max(c.strip.width(), best.strip.width());
    if (previous == nullptr || !c.feasible || !best.feasible ||
        std::abs(c.strip.width() - best.strip.width()) > options.continuity_tie * wider) {
      return c.BetterThan(best);
    }
    const auto distance = [&](const Posture& p) {
      return std::abs(p.lead_rad - previous->lead_rad) + std::abs(p.tilt_rad - previous->tilt_rad);
    };
    return distance(c.posture) < distance(best.posture);
  };
  constexpr int kCoarseHalf = 8, kZoomHalf = 3;
  double tilt_step = options.max_tilt_rad / kCoarseHalf;
  int half_count = kCoarseHalf;
  double centre = 0.0;
  Candidate best = LeadAtGougeBoundary(options, 0.0, place);
  while (true) {
    for (int j = -half_count; j <= half_count; ++j) {
      const double tilt = centre + j * tilt_step;
      if (j == 0 || std::abs(tilt) > options.max_tilt_rad + 1e-12) continue;
      const Candidate c = LeadAtGougeBoundary(options, tilt, place);
      if (preferred(c, best)) best = c;
    }
    if (tilt_step < options.angle_resolution_rad * kZoomHalf) break;
    centre = best.posture.tilt_rad;
    tilt_step /= kZoomHalf;
    half_count = kZoomHalf;
  }
  return best;
}

}  // namespace

bool PostureOptions::IsValid(std::string* why) const {
  FirstInvalid check;
  const double deg = kRadToDeg;
  std::ostringstream lead_range;
  lead_range << "[" << min_lead_rad * deg << ", " << max_lead_rad * deg << "]";
  check.Require(tolerance_mm > 0.0 && tolerance_mm <= 10.0,
          InvalidField("--tolerance_mm", tolerance_mm, "in (0, 10]"));
  check.Require(min_lead_rad > 0.0, InvalidField("--min_lead_deg", min_lead_rad * deg, "> 0"));
  check.Require(max_lead_rad >= min_lead_rad && max_lead_rad < M_PI / 2,
          InvalidField("--max_lead_deg", max_lead_rad * deg,
                       ">= --min_lead_deg and < 90"));
  check.Require(sturz_lead_rad >= min_lead_rad && sturz_lead_rad <= max_lead_rad,
          InvalidField("--lead_deg", sturz_lead_rad * deg,
                       "in [--min_lead_deg, --max_lead_deg] = " + lead_range.str()));
  check.Require(max_tilt_rad >= 0.0 && max_tilt_rad < M_PI / 2,
          InvalidField("--max_tilt_deg", max_tilt_rad * deg, "in [0, 90)"));
  check.Require(gouge_tolerance_mm >= 0.0,
          InvalidField("gouge_tolerance_mm", gouge_tolerance_mm, ">= 0"));
  check.Require(angle_resolution_rad > 0.0,
          InvalidField("angle_resolution_rad", angle_resolution_rad, "> 0"));
  check.Require(continuity_tie >= 0.0 && continuity_tie < 1.0,
          InvalidField("continuity_tie", continuity_tie, "in [0, 1)"));
  return check.Report(why);
}

PlacedTool PlaceTool(const TorusCutter& cutter, const CrossSection& section,
                     const Posture& posture) {
  PlacedTool tool;
  const double cl = std::cos(posture.lead_rad), sl = std::sin(posture.lead_rad);
  const double ct = std::cos(posture.tilt_rad), st = std::sin(posture.tilt_rad);
  tool.axis = (ct * (cl * section.n + sl * section.f) + st * section.b).normalized();
  Eigen::Vector3d contact, normal;
  ContactAt(section, posture.contact_s_mm, &contact, &normal);
  tool.tip = TipForContact(cutter, contact, normal, tool.axis);
  return tool;
}

Strip EvaluatePosture(const TorusCutter& cutter, const CrossSection& section,
                      const Posture& posture, double tolerance_mm) {
  const PlacedTool tool = PlaceTool(cutter, section, posture);
  return StripFromDeviation(section, CrossSectionDeviation(cutter, section, tool.tip, tool.axis),
                            tolerance_mm);
}

Posture ChoosePosture(PostureMethod method, const TorusCutter& cutter,
                      const CrossSection& section, const PostureOptions& options, Strip* strip,
                      const Posture* previous) {
  Candidate chosen;
  switch (method) {
    case PostureMethod::kSturz:
      chosen = Evaluate(cutter, section, Posture{options.sturz_lead_rad, 0.0, 0.0}, options);
      break;
    case PostureMethod::kMultiPoint:
      chosen = SearchLeadTilt(options, previous, [&](double lead, double tilt) {
        return Evaluate(cutter, section, Posture{lead, tilt, 0.0}, options);
      });
      break;
    case PostureMethod::kMidPointErrorControl:
      chosen = SearchLeadTilt(options, previous, [&](double lead, double tilt) {
        return CentredOnCc(cutter, section, Posture{lead, tilt, 0.0}, options);
      });
      break;
  }
  *strip = chosen.strip;
  return chosen.posture;
}

}  // namespace tpopt
