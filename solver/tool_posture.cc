#include "solver/tool_posture.h"

#include <algorithm>
#include <cmath>
#include <sstream>

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
// mid-point is the CC point. Moving the contact by ds moves the strip by
// about ds, so a few fixed-point steps s_c -= mid converge.
Candidate CentredOnCc(const TorusCutter& cutter, const CrossSection& section, Posture posture,
                      const PostureOptions& options) {
  const double reach = 0.9 * section.step_mm * section.centre;
  Candidate c = Evaluate(cutter, section, posture, options);
  for (int step = 0; step < 6 && std::abs(c.strip.mid()) > 0.25 * section.step_mm; ++step) {
    posture.contact_s_mm = std::clamp(posture.contact_s_mm - c.strip.mid(), -reach, reach);
    c = Evaluate(cutter, section, posture, options);
  }
  return c;
}

// Widest gouge-free strip over lead and tilt: a coarse grid over the search
// box, then a compass search from the best grid point with halving steps.
// Deterministic; robust to the flat and non-smooth width landscape (the
// width jumps where a second contact appears), where a gradient method is
// not.
template <typename Place>
Candidate SearchLeadTilt(const PostureOptions& options, Place place) {
  constexpr int kLeads = 8, kTilts = 9;
  const double lead_step = (options.max_lead_rad - options.min_lead_rad) / (kLeads - 1);
  const double tilt_step = 2 * options.max_tilt_rad / (kTilts - 1);
  Candidate best;
  bool have = false;
  for (int i = 0; i < kLeads; ++i) {
    for (int j = 0; j < kTilts; ++j) {
      const Candidate c =
          place(options.min_lead_rad + i * lead_step, -options.max_tilt_rad + j * tilt_step);
      if (!have || c.BetterThan(best)) best = c, have = true;
    }
  }
  double step_lead = 0.5 * lead_step, step_tilt = 0.5 * tilt_step;
  while (std::max(step_lead, step_tilt) > options.angle_resolution_rad) {
    bool improved = false;
    const double moves[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& m : moves) {
      const double lead = best.posture.lead_rad + m[0] * step_lead;
      const double tilt = best.posture.tilt_rad + m[1] * step_tilt;
      if (lead < options.min_lead_rad || lead > options.max_lead_rad ||
          std::abs(tilt) > options.max_tilt_rad) {
        continue;
      }
      const Candidate c = place(lead, tilt);
      if (c.BetterThan(best)) best = c, improved = true;
    }
    if (!improved) step_lead *= 0.5, step_tilt *= 0.5;
  }
  return best;
}

}  // namespace

bool PostureOptions::IsValid(std::string* why) const {
  std::ostringstream err;
  const double deg = 180.0 / M_PI;
  if (!(tolerance_mm > 0.0) || tolerance_mm > 10.0) {
    err << "tolerance " << tolerance_mm << " mm must be in (0, 10]";
  } else if (!(min_lead_rad > 0.0) || !(max_lead_rad >= min_lead_rad) ||
             max_lead_rad >= M_PI / 2) {
    err << "lead range [" << min_lead_rad * deg << ", " << max_lead_rad * deg
        << "] deg must satisfy 0 < min <= max < 90";
  } else if (!(sturz_lead_rad >= min_lead_rad && sturz_lead_rad <= max_lead_rad)) {
    err << "Sturz lead " << sturz_lead_rad * deg << " deg must lie in the lead range ["
        << min_lead_rad * deg << ", " << max_lead_rad * deg << "]";
  } else if (!(max_tilt_rad >= 0.0) || max_tilt_rad >= M_PI / 2) {
    err << "max tilt " << max_tilt_rad * deg << " deg must be in [0, 90)";
  } else if (!(gouge_tolerance_mm >= 0.0) || !(angle_resolution_rad > 0.0)) {
    err << "gouge tolerance and angle resolution must be positive";
  } else {
    return true;
  }
  if (why != nullptr) *why = err.str();
  return false;
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
                      const CrossSection& section, const PostureOptions& options, Strip* strip) {
  Candidate chosen;
  switch (method) {
    case PostureMethod::kSturz:
      chosen = Evaluate(cutter, section, Posture{options.sturz_lead_rad, 0.0, 0.0}, options);
      break;
    case PostureMethod::kMultiPoint:
      chosen = SearchLeadTilt(options, [&](double lead, double tilt) {
        return Evaluate(cutter, section, Posture{lead, tilt, 0.0}, options);
      });
      break;
    case PostureMethod::kMidPointErrorControl:
      chosen = SearchLeadTilt(options, [&](double lead, double tilt) {
        return CentredOnCc(cutter, section, Posture{lead, tilt, 0.0}, options);
      });
      break;
  }
  *strip = chosen.strip;
  return chosen.posture;
}

}  // namespace tpopt
