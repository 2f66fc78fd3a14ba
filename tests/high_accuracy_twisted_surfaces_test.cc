// Issue 16, item 2: on a strongly twisted impeller blade and a helicoid
// strip (closed forms in tests/analytic_surfaces.h, not in data/), from the
// CAM path of the issue (the SPO path with its tip 2 mm below the floor, a
// U/V bump of 0.03 and 0.3 deg of axis noise, 300 poses, R = 4, LinuxCNC's
// sim machine), the high-accuracy solve once ended 4 mm into the surface
// (an axis lying across it) or with flipped axes (A = 132.8 deg where the
// input's polar angle was 64 deg). Each case asserts, against the
// brute-force evaluator and the machine's own travel check:
//  - wherever the input is no more than the tolerance into the surface,
//    the output is not either;
//  - every output axis within its cone round its input axis;
//  - every output pose inside the travel.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

#include "model/eval/deviation.h"
#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "solver/smooth/smoothing_pipeline.h"
#include "tests/analytic_surfaces.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kOverhangMm = 2.0;

struct TwistedCase {
  const char* name;
  RuledSurface (*surface)(double twist_deg);
  double twist_deg;
  CutterSide side;
};

void PrintTo(const TwistedCase& c, std::ostream* os) { *os << c.name; }

class HighAccuracyTwistedSurfacesTest
    : public ::testing::TestWithParam<TwistedCase> {};

// Brute-force deviation of `path` on [u_min, u_max].
DeviationReport Brute(const RuledSurface& surface, const Cutter& cutter,
                      const ToolPath& path, const Machine& machine,
                      const DeviationOptions& model, double u_min,
                      double u_max) {
  DeviationOptions o = model;
  o.samples_u = 80;
  o.samples_v = 7;
  o.u_min = u_min;
  o.u_max = u_max;
  DeviationReport r;
  const Status s =
      EvaluateDeviationBruteForce(surface, cutter, path, &machine, o, 20, &r);
  EXPECT_TRUE(s.ok()) << s.message();
  return r;
}

TEST_P(HighAccuracyTwistedSurfacesTest, NoGougeNoFlipAndInsideTheTravel) {
  const TwistedCase& param = GetParam();
  const RuledSurface closed_form = param.surface(param.twist_deg);
  const RuledSurface surface(closed_form.name(), closed_form.rail(0),
                             closed_form.rail(1), param.side);
  Machine sim;
  ASSERT_TRUE(ReadMachineJson(testing::SourcePath(
                                  "data/machines/linuxcnc_xyzac_trt_sim.json"),
                              &sim)
                  .ok());
  FlankPathOptions g;
  g.poses = 300;
  g.cutter_radius_mm = 4.0;
  g.uv_distortion = 0.03;
  g.axis_noise_deg = 0.3;
  ToolPath cam;
  ASSERT_TRUE(GenerateFlankPath(surface, g, &cam).ok());
  for (ToolPose& p : cam.poses) p.p_w_tip -= kOverhangMm * p.a_w;
  Cutter cutter = *cam.cutter;
  cutter.flute_length_mm += kOverhangMm;
  cam.cutter = cutter;
  std::vector<JointVector> joints;
  ASSERT_TRUE(sim.AssignJoints(cam, &joints).ok());
  ASSERT_TRUE(sim.CheckTravel(cam, joints).ok())
      << "the input must fit the machine";

  SmoothingSettings settings;
  settings.mode = SmoothingMode::kHighAccuracy;
  SmoothingResult result;
  const Status s = RunSmoothing({&cam, &surface, &cutter, &sim}, settings, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  const ToolPath& out = result.output;
  ASSERT_EQ(out.poses.size(), cam.poses.size());

  // Inside the travel.
  ASSERT_TRUE(sim.AssignJoints(out, &joints).ok());
  const Status travel = sim.CheckTravel(out, joints);
  EXPECT_TRUE(travel.ok()) << travel.message();

  // No flip: every axis within its cone round the input's.
  const double cone_deg = settings.high_accuracy.axis_cone_deg;
  for (size_t i = 0; i < out.poses.size(); ++i) {
    const Eigen::Vector3d& a = out.poses[i].a_w;
    const Eigen::Vector3d& a0 = cam.poses[i].a_w;
    EXPECT_LE(std::atan2(a.cross(a0).norm(), a.dot(a0)) * 180 / M_PI, cone_deg)
        << "pose " << i;
  }

  // No gouge beyond the tolerance where the input had none.
  double u_min = 0, u_max = 0;
  ASSERT_TRUE(CoveredRangeU(surface, cam, &u_min, &u_max));
  const DeviationReport in =
      Brute(surface, cutter, cam, sim, settings.deviation, u_min, u_max);
  const DeviationReport got =
      Brute(surface, cutter, out, sim, settings.deviation, u_min, u_max);
  ASSERT_EQ(in.deviation_mm.size(), got.deviation_mm.size());
  const double tolerance_mm = settings.high_accuracy.tolerance_mm;
  int gouged = 0;
  double worst_mm = 0;
  for (size_t k = 0; k < got.deviation_mm.size(); ++k) {
    if (-in.deviation_mm[k] > tolerance_mm) continue;
    if (-got.deviation_mm[k] > tolerance_mm) {
      ++gouged;
      worst_mm = std::max(worst_mm, -got.deviation_mm[k]);
    }
  }
  EXPECT_EQ(gouged, 0) << gouged << " grid points gouged, worst " << worst_mm
                       << " mm into the surface (input overcut "
                       << in.max_overcut_mm << " mm, output "
                       << got.max_overcut_mm << " mm)";
}

std::string CaseName(const ::testing::TestParamInfo<TwistedCase>& info) {
  return info.param.name;
}

constexpr CutterSide kPlus = CutterSide::kPositive,
                     kMinus = CutterSide::kNegative;

INSTANTIATE_TEST_SUITE_P(
    Item2, HighAccuracyTwistedSurfacesTest,
    ::testing::Values(TwistedCase{"TwistedBlade60Plus", &testing::TwistedBlade,
                                  60.0, kPlus},
                      TwistedCase{"TwistedBlade60Minus", &testing::TwistedBlade,
                                  60.0, kMinus},
                      TwistedCase{"HelicoidStrip60Plus",
                                  &testing::HelicoidStrip, 60.0, kPlus},
                      TwistedCase{"HelicoidStrip60Minus",
                                  &testing::HelicoidStrip, 60.0, kMinus}),
    CaseName);

// The blade twisted by 70 deg with the cutter on its - side is refused: "the
// best path found is 0.0541 mm into the surface at (u 0, v 0), where the
// input was 0.000149 mm: beyond the tolerance of 0.01 mm at 5 of 4200 grid
// points, after 4 rounds". Not a wall's doing (it is refused with
// w_walls = 0 too): the excess is at the surface's end, u = 0, which the
// pipeline's end handling and tolerance active set own. Since stop 23 it is
// not refused: its run goes back as programmed (the input), which passes
// this test's assertions without smoothing anything, so it stays disabled
// until the solve itself holds the end.
INSTANTIATE_TEST_SUITE_P(DISABLED_RefusedAtTheSurfacesEnd,
                         HighAccuracyTwistedSurfacesTest,
                         ::testing::Values(TwistedCase{"TwistedBlade70Minus",
                                                       &testing::TwistedBlade,
                                                       70.0, kMinus}),
                         CaseName);

}  // namespace
}  // namespace tpopt
