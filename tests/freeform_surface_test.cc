// FreeformSurface against a polynomial it represents exactly, and its JSON
// reader's errors.
#include "model/geometry/freeform_surface.h"
#include "model/io/freeform_surface_json.h"

#include <fstream>

#include <gtest/gtest.h>

#include "tests/analytic_surfaces.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kK = 0.004, kHalf = 30.0;
// Uneven interior knots, so that several spans and the span search count.
const std::vector<double> kKnots = {0, 0, 0, 0, 0.2, 0.45, 0.5, 0.8, 1, 1, 1, 1};

TEST(FreeformSurfaceTest, ReproducesTheSaddleAndItsPartials) {
  const FreeformSurface saddle = testing::MakeSaddle(kK, kHalf, kKnots);
  for (double u : {0.0, 0.1, 0.45, 0.5, 0.77, 1.0}) {
    for (double v : {0.0, 0.33, 0.5, 0.9}) {
      const double x = -kHalf + 2 * kHalf * u, y = -kHalf + 2 * kHalf * v, dx = 2 * kHalf;
      const SurfaceDerivatives d = saddle.Evaluate(u, v);
      EXPECT_LT((d.p - Eigen::Vector3d(x, y, kK * (x * x - y * y))).norm(), 1e-9) << u << " " << v;
      EXPECT_LT((d.su - dx * Eigen::Vector3d(1, 0, 2 * kK * x)).norm(), 1e-8);
      EXPECT_LT((d.sv - dx * Eigen::Vector3d(0, 1, -2 * kK * y)).norm(), 1e-8);
      EXPECT_LT((d.suu - dx * dx * Eigen::Vector3d(0, 0, 2 * kK)).norm(), 1e-7);
      EXPECT_LT(d.suv.norm(), 1e-7);
      EXPECT_LT((d.svv - dx * dx * Eigen::Vector3d(0, 0, -2 * kK)).norm(), 1e-7);
    }
  }
}

TEST(FreeformSurfaceTest, CurvaturesAtTheSaddlePoint) {
  const FreeformSurface saddle = testing::MakeSaddle(kK, kHalf, kKnots);
  const SurfaceDerivatives d = saddle.Evaluate(0.5, 0.5);
  EXPECT_LT((saddle.ToolSideNormal(d) - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
  // z = k (x^2 - y^2): k1 = 2k along x (bending up, towards the cutter on
  // +z, so concave and positive), k2 = -2k along y.
  const PrincipalCurvatures c = saddle.Curvatures(d);
  EXPECT_NEAR(c.k_max, 2 * kK, 1e-12);
  EXPECT_NEAR(c.k_min, -2 * kK, 1e-12);
  EXPECT_NEAR(std::abs(c.dir_max.x()), 1.0, 1e-9);
  EXPECT_NEAR(saddle.NormalCurvature(d, Eigen::Vector3d(1, 1, 0)), 0.0, 1e-12);
  // Off the saddle point the Gaussian curvature is
  // -4k^2 / (1 + 4k^2 (x^2 + y^2))^2.
  const double x = -kHalf + 2 * kHalf * 0.8, y = -kHalf + 2 * kHalf * 0.3;
  const PrincipalCurvatures off = saddle.Curvatures(saddle.Evaluate(0.8, 0.3));
  const double g = 1 + 4 * kK * kK * (x * x + y * y);
  EXPECT_NEAR(off.k_max * off.k_min, -4 * kK * kK / (g * g), 1e-12);
}

TEST(FreeformSurfaceTest, PropellerBladeTurnsFromConcaveToConvexAcrossTheChord) {
  // The blade file's documented shape: along the mid-chord line the
  // chordwise section is a parabola of depth 3 mm over the 30 mm half chord
  // (curvature 2 * 3 / 30^2, concave towards the cutter) before x = 52 mm
  // and of depth -2.5 mm after x = 64 mm. The control net samples the shape
  // at the Greville points, so the spline follows it only approximately.
  FreeformSurface blade;
  const Status s = ReadFreeformSurfaceJson(
      testing::SourcePath("data/surfaces/propeller_blade_freeform.json"), &blade);
  ASSERT_TRUE(s.ok()) << s.message();
  const auto chordwise = [&](double u) {
    const SurfaceDerivatives d = blade.Evaluate(u, 0.5);
    return blade.NormalCurvature(d, d.sv);
  };
  EXPECT_NEAR(chordwise(0.2), 2 * 3.0 / 900, 0.1 * 2 * 3.0 / 900);
  EXPECT_NEAR(chordwise(0.8), -2 * 2.5 / 900, 0.1 * 2 * 2.5 / 900);
  // Most of the change happens within the 12 mm (u = 0.1) transition.
  EXPECT_GT(chordwise(0.42) - chordwise(0.55), 0.8 * (chordwise(0.2) - chordwise(0.8)));
}

std::string WriteFile(const testing::TempDir& dir, const std::string& text) {
  const std::string path = dir.File("s.json");
  std::ofstream(path) << text;
  return path;
}

const char kGood[] = R"({"name": "tiny", "units": "mm", "kind": "bspline_surface",
 "cutter_side": "negative", "degree_u": 3, "degree_v": 3,
 "knots_u": [0, 0, 0, 0, 2, 2, 2, 2], "knots_v": [0, 0, 0, 0, 1, 1, 1, 1],
 "control_points": [
  [[0, 0, 0], [0, 1, 0], [0, 2, 0], [0, 3, 0]],
  [[1, 0, 0], [1, 1, 1], [1, 2, 1], [1, 3, 0]],
  [[2, 0, 0], [2, 1, 1], [2, 2, 1], [2, 3, 0]],
  [[3, 0, 0], [3, 1, 0], [3, 2, 0], [3, 3, 0]]]})";

TEST(FreeformSurfaceTest, ReadsAFileAndNamesTheFieldAtFault) {
  testing::TempDir dir;
  FreeformSurface surface;
  Status s = ReadFreeformSurfaceJson(WriteFile(dir, kGood), &surface);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(surface.name(), "tiny");
  EXPECT_EQ(surface.cutter_side_sign(), -1.0);
  // The corners of a clamped net are interpolated.
  EXPECT_LT((surface.Evaluate(1, 1).p - Eigen::Vector3d(3, 3, 0)).norm(), 1e-12);

  const struct {
    std::string from, to, message;
  } kCases[] = {
      {"\"knots_v\"", "\"knots_w\"", "missing field \"knots_v\""},
      {"\"degree_u\": 3", "\"degree_u\": 2", "degree_u = 2"},
      {"\"kind\": \"bspline_surface\"", "\"kind\": \"ruled\"", "kind \"ruled\""},
      {"[1, 2, 1], [1, 3, 0]]", "[1, 2, 1]]", "control_points[1] has 3 points"},
      {"[2, 1, 1]", "[2, \"x\", 1]", "control_points[2][1][1] must be a number"},
      {"[0, 0, 0, 0, 2, 2, 2, 2]", "[0, 0, 0, 0, 2, 2, 2]", "knots_u"},
      {"\"tiny\",", "\"tiny\", ", ""},  // whitespace only: still fine
  };
  for (const auto& c : kCases) {
    std::string text = kGood;
    text.replace(text.find(c.from), c.from.size(), c.to);
    const std::string path = WriteFile(dir, text);
    s = ReadFreeformSurfaceJson(path, &surface);
    if (c.message.empty()) {
      EXPECT_TRUE(s.ok()) << s.message();
      continue;
    }
    ASSERT_FALSE(s.ok()) << c.to;
    EXPECT_NE(s.message().find(path), std::string::npos) << s.message();
    EXPECT_NE(s.message().find(c.message), std::string::npos) << s.message();
  }
  s = ReadFreeformSurfaceJson(WriteFile(dir, "{\"kind\": \n ["), &surface);
  EXPECT_NE(s.message().find("s.json:2: malformed JSON"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace tpopt
