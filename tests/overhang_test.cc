#include "solver/spline/overhang.h"

#include <gtest/gtest.h>

#include <random>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "model/path/rail_projection.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

// The generator's SPO path (tip on the floor, u = i / (n - 1)) with each
// tip moved down its axis by `overhang(i)`.
struct Case {
  RuledSurface surface;
  ToolPath path;
  std::vector<double> u;
};

Case Make(double axis_noise_deg,
          const std::function<double(size_t)>& overhang) {
  Case c;
  EXPECT_TRUE(
      ReadSurfaceJson(testing::SourcePath("data/surfaces/jcde2022.json"),
                      &c.surface)
          .ok());
  FlankPathOptions g;
  g.poses = 120;
  g.axis_noise_deg = axis_noise_deg;
  EXPECT_TRUE(GenerateFlankPath(c.surface, g, &c.path).ok());
  for (size_t i = 0; i < c.path.poses.size(); ++i) {
    ToolPose& p = c.path.poses[i];
    // Placed as the CAM does: R along the normal made orthogonal
    // to the (noisy) axis, then down the axis.
    const double u = i / (g.poses - 1.0);
    const Eigen::Vector3d n = c.surface.Normal(u, 0.0);
    const Eigen::Vector3d n_perp = (n - n.dot(p.a_w) * p.a_w).normalized();
    p.p_w_tip = c.surface.rail(0).Point(u) + 4.0 * n_perp - overhang(i) * p.a_w;
    c.u.push_back(u);
  }
  return c;
}

TEST(OverhangTest, ConstantAndLinearOverhangsComeThroughExactly) {
  for (const auto& overhang : std::vector<std::function<double(size_t)>>{
           [](size_t) { return 2.0; },
           [](size_t i) { return 0.5 + 0.02 * i; }}) {
    const Case c = Make(0.0, overhang);
    std::vector<double> h;
    ASSERT_TRUE(PoseOverhangs(c.surface.rail(0), c.path, c.u, &h).ok());
    for (size_t i = 0; i < h.size(); ++i)
      EXPECT_NEAR(h[i], overhang(i), 1e-6) << i;
  }
}

TEST(OverhangTest, NoiseAndASpikeOfAFewPosesAreSmoothedAway) {
  // Pose by pose the height jitters by up to 0.15 mm and three poses jump
  // by 0.2 mm; the smoothed overhang stays within 0.1 mm of the 2 mm
  // programmed (measured 0.054) and varies by far less than the jitter
  // between neighbours.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  std::vector<double> noise(120);
  for (double& e : noise) e = jitter(rng);
  const Case c = Make(0.3, [&](size_t i) {
    return 2.0 + noise[i] + (i >= 60 && i < 63 ? 0.2 : 0);
  });
  std::vector<double> h;
  ASSERT_TRUE(PoseOverhangs(c.surface.rail(0), c.path, c.u, &h).ok());
  double worst_step = 0.0, worst_input_step = 0.0;
  for (size_t i = 0; i < h.size(); ++i) {
    EXPECT_NEAR(h[i], 2.0, 0.1) << i;
    if (i == 0) continue;
    worst_step = std::max(worst_step, std::abs(h[i] - h[i - 1]));
    worst_input_step = std::max(worst_input_step, std::abs(noise[i] - noise[i - 1]));
  }
  EXPECT_LT(worst_step, 0.1 * worst_input_step);
}

TEST(OverhangTest, ATipAboveTheFloorIsBroughtDownToIt) {
  const Case c = Make(0.0, [](size_t) { return -1.5; });
  std::vector<double> h;
  ASSERT_TRUE(PoseOverhangs(c.surface.rail(0), c.path, c.u, &h).ok());
  for (double x : h) EXPECT_EQ(x, 0.0);
}

}  // namespace
}  // namespace tpopt
