#include "model/eval/random_cases.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "model/base/invalid_field.h"
#include "model/path/path_generator.h"
#include "model/base/units.h"

namespace tpopt {
namespace {

class Draw {
 public:
  explicit Draw(unsigned seed) : rng_(seed) {}
  double Uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  int Int(int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng_);
  }
  bool Chance(double p) { return Uniform(0.0, 1.0) < p; }
  double Sign() { return Chance(0.5) ? 1.0 : -1.0; }
  std::mt19937* rng() { return &rng_; }

 private:
  std::mt19937 rng_;
};

// The local-frame geometry of the surface at arc length s in [-L/2, L/2] of
// rail 0: the rail point, and the ruling direction.
struct LocalSurface {
  double size_mm, height_mm, curvature_per_mm, bow_mm, lean_rad, twist_rad;

  Eigen::Vector3d Rail(double s) const {
    const double k = curvature_per_mm;
    const double x = std::abs(k) < 1e-12 ? s : std::sin(k * s) / k;
    const double y = std::abs(k) < 1e-12 ? 0.0 : (1.0 - std::cos(k * s)) / k;
    const double w = 2.0 * s / size_mm;
    return {x, y, bow_mm * (1.0 - w * w)};
  }
  Eigen::Vector3d InPlaneNormal(double s) const {
    return {-std::sin(curvature_per_mm * s), std::cos(curvature_per_mm * s),
            0.0};
  }
  double Lean(double s) const { return lean_rad + twist_rad * s / size_mm; }
  Eigen::Vector3d Ruling(double s) const {
    const double lean = Lean(s);
    return std::cos(lean) * Eigen::Vector3d::UnitZ() +
           std::sin(lean) * InPlaneNormal(s);
  }
};

// Clamped uniform knots on [0, 1] for `n` control points of `degree`.
std::vector<double> ClampedUniformKnots(int degree, int n) {
  std::vector<double> knots(static_cast<size_t>(n + degree + 1));
  const int spans = n - degree;
  for (size_t i = 0; i < knots.size(); ++i) {
    const int k = static_cast<int>(i) - degree;
    knots[i] = std::clamp(static_cast<double>(k) / spans, 0.0, 1.0);
  }
  return knots;
}

Status BuildSurface(const LocalSurface& local, int degree, int control_points,
                    const Eigen::Matrix3d& rotation,
                    const Eigen::Vector3d& centre_w, CutterSide side,
                    unsigned seed, RuledSurface* surface) {
  const std::vector<double> knots = ClampedUniformKnots(degree, control_points);
  std::vector<Eigen::Vector3d> p0, p1;
  for (int i = 0; i < control_points; ++i) {
    double greville = 0.0;
    for (int j = 1; j <= degree; ++j)
      greville += knots[static_cast<size_t>(i + j)];
    greville /= degree;
    const double s = (greville - 0.5) * local.size_mm;
    const Eigen::Vector3d c1 = local.Rail(s);
    p0.push_back(rotation * c1 + centre_w);
    p1.push_back(rotation * (c1 + local.height_mm * local.Ruling(s)) +
                 centre_w);
  }
  BSplineCurve rail0, rail1;
  const std::string name = "random case " + std::to_string(seed);
  RETURN_IF_ERROR(BSplineCurve::Create(degree, knots, p0, name + ": rail 0", &rail0));
  RETURN_IF_ERROR(BSplineCurve::Create(degree, knots, p1, name + ": rail 1", &rail1));
  *surface = RuledSurface(name, rail0, rail1, side);
  return Status::Ok();
}

// Tilts `axis` by `angle_rad` about a direction normal to it at `phi_rad`.
Eigen::Vector3d Tilt(const Eigen::Vector3d& axis, double angle_rad,
                     double phi_rad) {
  const Eigen::Vector3d e1 = axis.unitOrthogonal();
  const Eigen::Vector3d e2 = axis.cross(e1);
  const Eigen::Vector3d about = std::cos(phi_rad) * e1 + std::sin(phi_rad) * e2;
  return Eigen::AngleAxisd(angle_rad, about) * axis;
}

double Bump(const RandomCaseParameters& p, double u) {
  const double x = (u - p.uv_bump_center) / p.uv_bump_width;
  if (std::abs(x) >= 0.5) return 0.0;
  const double c = std::cos(M_PI * x);
  return p.uv_bump * c * c;
}

// The CAM path of the header comment. `noise` holds two numbers per pose of
// the body (tilt angle, direction), drawn once so that every placement of
// the part gets the same path.
Status BuildCamPath(const RuledSurface& surface, const RandomCaseParameters& p,
                    const std::vector<double>& u_body,
                    const std::vector<double>& noise, double feed_mm_per_min,
                    ToolPath* path, std::vector<double>* cam_u) {
  const double r = p.cutter_radius_mm;
  const double taper = p.taper_deg * kDegToRad;
  ToolPath out;
  for (size_t i = 0; i < u_body.size(); ++i) {
    const double u = u_body[i];
    const double u2 = std::clamp(u + Bump(p, u), 0.0, 1.0);
    const Eigen::Vector3d c1 = surface.rail(0).Point(u);
    const Eigen::Vector3d e = (surface.rail(1).Point(u2) - c1).normalized();
    const Eigen::Vector3d n = surface.Normal(u, 0.0);
    const Eigen::Vector3d n_e = n - n.dot(e) * e;
    if (!(n_e.norm() > 1e-9)) {
      std::ostringstream err;
      err << surface.name()
          << ": the CAM ruling is normal to the surface at u = " << u;
      return Status::Error(err.str());
    }
    Eigen::Vector3d a =
        std::cos(taper) * e + std::sin(taper) * n_e.normalized();
    a = Tilt(a, noise[2 * i], noise[2 * i + 1]).normalized();
    const Eigen::Vector3d n_perp = (n - n.dot(a) * a).normalized();
    ToolPose pose;
    pose.feed_mm_per_min = feed_mm_per_min;
    pose.a_w = a;
    pose.p_w_tip =
        c1 + (r + p.overhang_mm * std::tan(taper)) * n_perp - p.overhang_mm * a;
    out.poses.push_back(pose);
  }
  // Lead-in and lead-out: the tip goes on straight beyond each end.
  const ToolPose first = out.poses.front(), last = out.poses.back();
  const Eigen::Vector3d in_dir =
      (first.p_w_tip - out.poses[1].p_w_tip).normalized();
  const Eigen::Vector3d out_dir =
      (last.p_w_tip - out.poses[out.poses.size() - 2].p_w_tip).normalized();
  std::vector<ToolPose> lead_in;
  for (int k = p.lead_in_poses; k >= 1; --k) {
    ToolPose pose = first;
    pose.p_w_tip += k * p.lead_step_mm * in_dir;
    lead_in.push_back(pose);
  }
  out.poses.insert(out.poses.begin(), lead_in.begin(), lead_in.end());
  *cam_u = std::vector<double>(lead_in.size(), std::nan(""));
  cam_u->insert(cam_u->end(), u_body.begin(), u_body.end());
  for (int k = 1; k <= p.lead_out_poses; ++k) {
    ToolPose pose = last;
    pose.p_w_tip += k * p.lead_step_mm * out_dir;
    out.poses.push_back(pose);
    cam_u->push_back(std::nan(""));
  }
  *path = std::move(out);
  return Status::Ok();
}

// Empty when every path fits `machine`, else which does not and why.
std::string FitNote(const Machine& machine, const RandomCase& c) {
  const std::pair<const char*, const ToolPath*> paths[] = {
      {"CAM path", &c.cam_path},
      {"clean SPO", &c.clean_spo},
      {"clean DPO", &c.clean_dpo}};
  for (const auto& [name, path] : paths) {
    std::vector<JointVector> joints;
    Status s = machine.AssignJoints(*path, &joints);
    if (s.ok()) s = machine.CheckTravel(*path, joints);
    if (!s.ok()) return std::string(name) + ": " + s.message();
  }
  return "";
}

}  // namespace

bool RandomCaseOptions::IsValid(std::string* why) const {
  std::string problem;
  if (poses < 4) {
    problem = InvalidField("poses", poses, ">= 4");
  } else if (!(near_pole_fraction >= 0 && near_pole_fraction <= 1)) {
    problem = InvalidField("near_pole_fraction", near_pole_fraction, "in [0, 1]");
  } else if (!(std::isfinite(feed_mm_per_min) && feed_mm_per_min > 0)) {
    problem = InvalidField("feed_mm_per_min", feed_mm_per_min, "finite and > 0");
  } else {
    return true;
  }
  if (why != nullptr) *why = problem;
  return false;
}

Status MakeRandomCase(unsigned seed, const RandomCaseOptions& options,
                      const std::vector<Machine>& machines, RandomCase* out) {
  CHECK(out != nullptr);
  CHECK(!machines.empty());
  std::string why;
  if (!options.IsValid(&why)) return Status::Error("random case: " + why);
  Draw draw(seed);
  RandomCase c;
  c.seed = seed;
  RandomCaseParameters& p = c.parameters;
  c.machine = machines[static_cast<size_t>(
      draw.Int(0, static_cast<int>(machines.size()) - 1))];

  // The surface.
  p.rail_degree = draw.Int(1, 3);
  p.size_mm = draw.Uniform(20.0, 150.0);
  p.height_mm = std::clamp(p.size_mm * draw.Uniform(0.25, 0.6), 10.0, 60.0);
  p.cutter_radius_mm = draw.Uniform(2.0, 8.0);
  // Wrap no tighter than a rail curvature radius of 3 cutter radii, so an
  // offset on the concave side stays regular.
  const double max_wrap_rad =
      std::min(M_PI / 2, p.size_mm / (3.0 * p.cutter_radius_mm));
  p.wrap_deg = p.rail_degree == 1
                   ? 0.0
                   : draw.Sign() * draw.Uniform(0.0, max_wrap_rad) / kDegToRad;
  p.twist_deg = draw.Sign() * draw.Uniform(5.0, 50.0);
  const double bow_mm =
      p.rail_degree == 1 ? 0.0 : draw.Uniform(-0.05, 0.05) * p.size_mm;
  p.near_pole = draw.Chance(options.near_pole_fraction);
  const double phi_rad = draw.Uniform(-M_PI, M_PI);
  Eigen::Matrix3d rotation;
  if (p.near_pole) {
    // The ruling leans through 0 at u_pole; the part is tilted about the
    // rail's in-plane normal there, so the ruling passes pole_offset from +Z.
    const double u_pole = draw.Uniform(0.3, 0.7);
    p.lean_deg = -p.twist_deg * (u_pole - 0.5);
    p.pole_offset_deg = draw.Uniform(0.3, 3.0);
    p.tilt_deg = p.pole_offset_deg;
    const double s_pole = (u_pole - 0.5) * p.size_mm;
    const LocalSurface at{
        p.size_mm, p.height_mm, p.wrap_deg * kDegToRad / p.size_mm,
        bow_mm,    0,           0};
    rotation = Eigen::AngleAxisd(phi_rad, Eigen::Vector3d::UnitZ())
                   .toRotationMatrix() *
               Eigen::AngleAxisd(draw.Sign() * p.pole_offset_deg * kDegToRad,
                                 at.InPlaneNormal(s_pole))
                   .toRotationMatrix();
  } else {
    p.lean_deg = draw.Sign() * draw.Uniform(5.0, 25.0);
    p.tilt_deg = draw.Uniform(0.0, 25.0);
    const double tilt_about_rad = draw.Uniform(-M_PI, M_PI);
    rotation = Eigen::AngleAxisd(phi_rad, Eigen::Vector3d::UnitZ())
                   .toRotationMatrix() *
               Eigen::AngleAxisd(p.tilt_deg * kDegToRad,
                                 Eigen::Vector3d(std::cos(tilt_about_rad),
                                                 std::sin(tilt_about_rad), 0.0))
                   .toRotationMatrix();
  }
  const LocalSurface local{p.size_mm,
                           p.height_mm,
                           p.wrap_deg * kDegToRad / p.size_mm,
                           bow_mm,
                           p.lean_deg * kDegToRad,
                           p.twist_deg * kDegToRad};
  p.side = draw.Chance(0.5) ? CutterSide::kPositive : CutterSide::kNegative;
  const int control_points =
      p.rail_degree == 1 ? 2 : p.rail_degree + 1 + draw.Int(0, 3);

  // The CAM conventions.
  p.taper_deg = draw.Chance(0.5) ? 0.0 : draw.Uniform(0.0, 5.0);
  p.overhang_mm = draw.Uniform(0.0, 3.0);
  if (draw.Chance(0.7)) {
    p.uv_bump = draw.Sign() * draw.Uniform(0.0, 0.03);
    p.uv_bump_center = draw.Uniform(0.2, 0.8);
    p.uv_bump_width = draw.Uniform(0.05, 0.2);
  }
  p.axis_noise_deg = draw.Uniform(0.0, 0.5);
  p.lead_in_poses = draw.Int(0, 3);
  p.lead_out_poses = draw.Int(0, 3);
  p.lead_step_mm = draw.Uniform(0.5, 3.0);
  p.micro_steps = draw.Int(0, 3);
  // Uneven spacing: gaps of random weight, and a few extra poses 1 um
  // (of rail arc length) after a pose of the body.
  std::vector<double> gaps(static_cast<size_t>(options.poses - 1));
  for (double& g : gaps) g = draw.Uniform(0.3, 1.7);
  std::vector<double> u_body(1, 0.0);
  double total = 0.0;
  for (double g : gaps) total += g;
  for (double g : gaps)
    u_body.push_back(std::min(1.0, u_body.back() + g / total));
  u_body.back() = 1.0;
  // Noise: a tilt and its direction per body pose, drawn once so that every
  // placement of the part gets the same path; a pose 1 um after another
  // has that pose's axis error, as a CAM's near-duplicate point would.
  std::vector<double> body_noise;
  for (size_t i = 0; i < u_body.size(); ++i) {
    body_noise.push_back(std::normal_distribution<double>(
        0.0, p.axis_noise_deg * kDegToRad)(*draw.rng()));
    body_noise.push_back(draw.Uniform(0.0, 2.0 * M_PI));
  }
  std::vector<int> micro_after;
  for (int k = 0; k < p.micro_steps; ++k)
    micro_after.push_back(draw.Int(1, options.poses - 3));
  std::sort(micro_after.begin(), micro_after.end());
  micro_after.erase(std::unique(micro_after.begin(), micro_after.end()),
                    micro_after.end());
  p.micro_steps = static_cast<int>(micro_after.size());

  // Places to try, part centre in W, mm: the pivot first.
  const Eigen::Vector3d placements[] = {{0, 0, 0},  {0, 0, -30}, {0, 0, 30},
                                        {0, 30, 0}, {0, -30, 0}, {0, 0, -60}};
  bool placed = false;
  for (const Eigen::Vector3d& centre : placements) {
    RandomCase trial = c;
    trial.parameters.placement_w_mm = centre;
    RETURN_IF_ERROR(BuildSurface(local, p.rail_degree, control_points, rotation, centre, p.side,
                                 seed, &trial.surface));
    std::vector<double> u, noise;
    size_t next_micro = 0;
    for (size_t i = 0; i < u_body.size(); ++i) {
      u.push_back(u_body[i]);
      noise.insert(noise.end(), {body_noise[2 * i], body_noise[2 * i + 1]});
      if (next_micro < micro_after.size() &&
          micro_after[next_micro] == static_cast<int>(i)) {
        const double speed =
            trial.surface.rail(0).Evaluate(u_body[i], 1)[1].norm();
        u.push_back(u_body[i] + 1e-3 / speed);
        noise.insert(noise.end(), {body_noise[2 * i], body_noise[2 * i + 1]});
        ++next_micro;
      }
    }
    RETURN_IF_ERROR(BuildCamPath(trial.surface, p, u, noise, options.feed_mm_per_min,
                                 &trial.cam_path, &trial.cam_u));
    FlankPathOptions g;
    g.cutter_radius_mm = p.cutter_radius_mm;
    g.poses = options.poses;
    g.feed_mm_per_min = options.feed_mm_per_min;
    g.taper_rad = p.taper_deg * kDegToRad;
    g.strategy = FlankStrategy::kSinglePointOffset;
    RETURN_IF_ERROR(GenerateFlankPath(trial.surface, g, &trial.clean_spo));
    g.strategy = FlankStrategy::kDoublePointOffset;
    RETURN_IF_ERROR(GenerateFlankPath(trial.surface, g, &trial.clean_dpo));
    trial.cutter = *trial.clean_dpo.cutter;
    trial.cutter.flute_length_mm += p.overhang_mm;
    for (ToolPath* path :
         {&trial.cam_path, &trial.clean_spo, &trial.clean_dpo}) {
      path->cutter = trial.cutter;
    }
    trial.fit_note = FitNote(trial.machine, trial);
    trial.fits_machine = trial.fit_note.empty();
    if (!placed || trial.fits_machine) {
      const bool fits = trial.fits_machine;
      c = std::move(trial);
      placed = true;
      if (fits) break;
    }
  }
  std::ostringstream d;
  d << "seed " << seed << ": " << c.machine.name << ", degree " << p.rail_degree
    << ", size " << p.size_mm << " x " << p.height_mm << " mm, wrap "
    << p.wrap_deg << " deg, twist " << p.twist_deg << " deg, lean "
    << p.lean_deg << " deg, tilt " << p.tilt_deg << " deg"
    << (p.near_pole ? ", near the pole" : "") << ", side "
    << (p.side == CutterSide::kPositive ? "+" : "-") << ", R "
    << p.cutter_radius_mm << " mm, taper " << p.taper_deg << " deg, overhang "
    << p.overhang_mm << " mm, uv bump " << p.uv_bump << ", noise "
    << p.axis_noise_deg << " deg, lead " << p.lead_in_poses << "+"
    << p.lead_out_poses << " x " << p.lead_step_mm << " mm, " << p.micro_steps
    << " 1-um steps, " << c.cam_path.poses.size() << " poses"
    << (c.fits_machine ? "" : "; does not fit: " + c.fit_note);
  c.description = d.str();
  c.cam_path.title = "random case " + d.str();
  *out = std::move(c);
  return Status::Ok();
}

}  // namespace tpopt
