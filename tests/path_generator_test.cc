#include "model/path/path_generator.h"

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

double DistanceToLine(const Eigen::Vector3d& q, const ToolPose& pose) {
  const Eigen::Vector3d d = q - pose.p_w_tip;
  return (d - d.dot(pose.a_w) * pose.a_w).norm();
}

RuledSurface Shared(const std::string& name) {
  RuledSurface s;
  EXPECT_TRUE(ReadSurfaceJson(testing::SourcePath("data/surfaces/" + name + ".json"), &s).ok());
  return s;
}

double MaxAxisStepDeg(const ToolPath& path) {
  double worst = 0.0;
  for (size_t i = 1; i < path.poses.size(); ++i) {
    const double c = path.poses[i].a_w.dot(path.poses[i - 1].a_w);
    worst = std::max(worst, std::acos(std::clamp(c, -1.0, 1.0)) * 180 / M_PI);
  }
  return worst;
}

TEST(PathGeneratorTest, SpoOnADevelopableSurfaceHoldsTheWholeRulingAtR) {
  // A plane: two parallel straight rails.
  BSplineCurve c1, c2;
  ASSERT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 0, 0}, {50, 0, 0}}, "c1", &c1).ok());
  ASSERT_TRUE(BSplineCurve::Create(1, {0, 0, 1, 1}, {{0, 5, 20}, {50, 5, 20}}, "c2", &c2).ok());
  const RuledSurface plane("plane", c1, c2, CutterSide::kPositive);
  FlankPathOptions o;
  o.poses = 11;
  ToolPath path;
  ASSERT_TRUE(GenerateFlankPath(plane, o, &path).ok());
  ASSERT_EQ(path.poses.size(), 11u);
  for (size_t i = 0; i < path.poses.size(); ++i) {
    const double u = i / 10.0;
    EXPECT_NEAR(path.poses[i].a_w.norm(), 1.0, 1e-12);
    EXPECT_LT((path.poses[i].a_w - plane.Dv(u).normalized()).norm(), 1e-12);
    for (double v : {0.0, 0.5, 1.0}) {
      EXPECT_NEAR(DistanceToLine(plane.Point(u, v), path.poses[i]), 4.0, 1e-12);
    }
  }
  ASSERT_TRUE(path.cutter.has_value());
  EXPECT_NEAR(path.cutter->flute_length_mm, 1.25 * plane.Dv(0).norm(), 1e-12);
}

TEST(PathGeneratorTest, DpoOnTheHyparTouchesBothRulingEnds) {
  const RuledSurface hypar = Shared("hypar");
  FlankPathOptions o;
  o.strategy = FlankStrategy::kDoublePointOffset;
  o.poses = 21;
  ToolPath path;
  ASSERT_TRUE(GenerateFlankPath(hypar, o, &path).ok());
  ToolPath spo;
  o.strategy = FlankStrategy::kSinglePointOffset;
  ASSERT_TRUE(GenerateFlankPath(hypar, o, &spo).ok());
  for (size_t i = 0; i < path.poses.size(); ++i) {
    const double u = i / 20.0;
    // The offset points of both ends lie on the axis, so both ends sit at
    // R to first order (R cos of the small axis-to-ruling angle).
    for (double v : {0.0, 1.0}) {
      const Eigen::Vector3d offset = hypar.Point(u, v) + 4.0 * hypar.Normal(u, v);
      EXPECT_NEAR(DistanceToLine(offset, path.poses[i]), 0.0, 1e-9);
      EXPECT_NEAR(DistanceToLine(hypar.Point(u, v), path.poses[i]), 4.0, 1e-4);
    }
  }
  // The static cylinder of a pose cuts into the neighbouring rulings; on the
  // twisted hypar SPO (tangent only at the bottom) cuts deeper than DPO.
  auto penetration = [&](const ToolPath& p) {
    double deepest = 0.0;
    const ToolPose& mid = p.poses[10];
    for (double u = 0.4; u <= 0.6; u += 0.001) {
      for (double v = 0.0; v <= 1.0; v += 0.05) {
        deepest = std::max(deepest, 4.0 - DistanceToLine(hypar.Point(u, v), mid));
      }
    }
    return deepest;
  };
  EXPECT_GT(penetration(spo), 0.005);
  EXPECT_GT(penetration(spo), 2 * penetration(path));
}

// A tapered cutter: SPO lays the cone's generator on the ruling (both ends
// on the flank, measured normal to it), DPO puts both ruling ends on the
// cone; the cutter carries the taper.
TEST(PathGeneratorTest, TaperedCutterTouchesTheRulingEnds) {
  const RuledSurface hypar = Shared("hypar");
  FlankPathOptions o;
  o.poses = 11;
  o.taper_rad = 4.0 * M_PI / 180;
  for (FlankStrategy strategy :
       {FlankStrategy::kSinglePointOffset, FlankStrategy::kDoublePointOffset}) {
    o.strategy = strategy;
    ToolPath path;
    ASSERT_TRUE(GenerateFlankPath(hypar, o, &path).ok());
    ASSERT_TRUE(path.cutter.has_value());
    EXPECT_EQ(path.cutter->taper_rad, o.taper_rad);
    for (size_t i = 0; i < path.poses.size(); ++i) {
      const ToolPose& pose = path.poses[i];
      EXPECT_NEAR(pose.a_w.norm(), 1.0, 1e-12);
      for (double v : {0.0, 1.0}) {
        const double d =
            SignedDistanceToFlank<double>(*path.cutter, hypar.Point(i / 10.0, v), pose.p_w_tip,
                                          pose.a_w);
        // SPO: exact along the whole ruling on its own pose; DPO: the fixed
        // point to well under a micrometre.
        EXPECT_NEAR(d, 0.0, strategy == FlankStrategy::kSinglePointOffset ? 1e-9 : 1e-6)
            << "pose " << i << " v " << v;
      }
    }
  }
  o.taper_rad = M_PI / 4;
  ToolPath path;
  EXPECT_FALSE(GenerateFlankPath(hypar, o, &path).ok());
}

TEST(PathGeneratorTest, UvDistortionMakesLocalAxisJumps) {
  const RuledSurface blade = Shared("impeller_blade");
  FlankPathOptions o;
  ToolPath clean, distorted, zero;
  ASSERT_TRUE(GenerateFlankPath(blade, o, &clean).ok());
  o.uv_distortion = 0.0;
  ASSERT_TRUE(GenerateFlankPath(blade, o, &zero).ok());
  o.uv_distortion = 0.03;
  ASSERT_TRUE(GenerateFlankPath(blade, o, &distorted).ok());
  for (size_t i = 0; i < clean.poses.size(); ++i) {
    EXPECT_EQ(zero.poses[i].a_w, clean.poses[i].a_w);
  }
  EXPECT_GT(MaxAxisStepDeg(distorted), 3.0 * MaxAxisStepDeg(clean));
  // Outside the bump (|u - 0.5| >= 0.04) nothing changes.
  for (size_t i = 0; i < clean.poses.size(); ++i) {
    const double u = i / 299.0;
    if (std::abs(u - 0.5) >= 0.04) {
      EXPECT_EQ(distorted.poses[i].a_w, clean.poses[i].a_w) << i;
    }
  }
}

TEST(PathGeneratorTest, AxisNoiseIsDeterministicWithTheRequestedSpread) {
  const RuledSurface blade = Shared("impeller_blade");
  FlankPathOptions o;
  o.axis_noise_deg = 0.3;
  o.poses = 2000;
  ToolPath a, b, clean;
  ASSERT_TRUE(GenerateFlankPath(blade, o, &a).ok());
  ASSERT_TRUE(GenerateFlankPath(blade, o, &b).ok());
  o.axis_noise_deg = 0.0;
  ASSERT_TRUE(GenerateFlankPath(blade, o, &clean).ok());
  double sum_sq = 0.0;
  for (size_t i = 0; i < a.poses.size(); ++i) {
    EXPECT_EQ(a.poses[i].a_w, b.poses[i].a_w);
    const double angle = std::acos(std::clamp(a.poses[i].a_w.dot(clean.poses[i].a_w), -1.0, 1.0));
    sum_sq += angle * angle;
  }
  const double rms_deg = std::sqrt(sum_sq / a.poses.size()) * 180 / M_PI;
  EXPECT_NEAR(rms_deg, 0.3, 0.03);
}

TEST(PathGeneratorTest, RejectsBadOptionsNamingTheValue) {
  const RuledSurface hypar = Shared("hypar");
  ToolPath path;
  FlankPathOptions o;
  o.cutter_radius_mm = -1;
  Status s = GenerateFlankPath(hypar, o, &path);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("-1"), std::string::npos) << s.message();
  o = FlankPathOptions();
  o.poses = 1;
  EXPECT_FALSE(GenerateFlankPath(hypar, o, &path).ok());
  o = FlankPathOptions();
  o.uv_distortion = std::nan("");
  EXPECT_FALSE(GenerateFlankPath(hypar, o, &path).ok());
}

TEST(PathGeneratorTest, RepeatedPassesRunOneAfterAnotherWithARapidBetween) {
  ToolPath pass;
  for (int i = 0; i < 4; ++i) {
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(i, 0, 0);
    pose.rapid = i == 0;  // a pass may start with a rapid of its own
    pass.poses.push_back(pose);
  }
  pass.title = "pass";
  const ToolPath three = RepeatedPasses(pass, 3);
  ASSERT_EQ(three.poses.size(), 12u);
  EXPECT_EQ(three.title, "pass");
  for (size_t i = 0; i < three.poses.size(); ++i) {
    EXPECT_EQ(three.poses[i].p_w_tip, pass.poses[i % 4].p_w_tip) << i;
    // The path starts as a cut; each later pass starts with a rapid.
    EXPECT_EQ(three.poses[i].rapid, i == 4 || i == 8) << i;
  }
  EXPECT_TRUE(RepeatedPasses(pass, 0).poses.empty());
}

}  // namespace
}  // namespace tpopt
