#include "apps/vtk_scene.h"

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

class VtkSceneTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(
        ReadSurfaceJson(testing::SourcePath("data/surfaces/hypar.json"), &surface_).ok());
    FlankPathOptions options;
    options.poses = 12;
    ASSERT_TRUE(GenerateFlankPath(surface_, options, &path_).ok());
    cutter_.flute_length_mm = 30.0;
    grid_.u = {0.1, 0.4, 0.9};
    grid_.v = {0.0, 0.25, 0.5, 1.0};
    for (size_t i = 0; i < grid_.u.size() * grid_.v.size(); ++i) {
      grid_.deviation_mm.push_back(0.001 * i - 0.005);
    }
  }

  RuledSurface surface_;
  ToolPath path_;
  Cutter cutter_;
  SurfaceGrid grid_;
};

TEST_F(VtkSceneTest, SurfaceGridCarriesItsDeviationAndToolFollows) {
  const PolyData scene = BuildPathScene(path_, cutter_, &surface_, grid_);
  const size_t nu = grid_.u.size(), nv = grid_.v.size(), n = path_.poses.size();
  ASSERT_EQ(scene.points_w.size(), nu * nv + 2 * n);
  EXPECT_EQ(scene.polys.size(), (nu - 1) * (nv - 1));
  ASSERT_EQ(scene.lines.size(), n + 1);
  ASSERT_EQ(scene.point_scalars.size(), 2u);
  const std::vector<double>& deviation = scene.point_scalars[0].second;
  const std::vector<double>& part = scene.point_scalars[1].second;
  EXPECT_EQ(scene.point_scalars[0].first, "deviation_mm");
  for (size_t iu = 0; iu < nu; ++iu) {
    for (size_t iv = 0; iv < nv; ++iv) {
      const size_t k = iu * nv + iv;
      EXPECT_LT((scene.points_w[k] - surface_.Point(grid_.u[iu], grid_.v[iv])).norm(), 1e-12);
      EXPECT_EQ(deviation[k], grid_.deviation_mm[k]);
      EXPECT_EQ(part[k], kSurfacePart);
    }
  }
  // Each quad's corners are neighbours on the grid: two steps of u, two of v.
  for (const std::vector<int>& quad : scene.polys) {
    ASSERT_EQ(quad.size(), 4u);
    EXPECT_EQ(quad[1] - quad[0], static_cast<int>(nv));
    EXPECT_EQ(quad[2] - quad[1], 1);
    EXPECT_EQ(quad[3], quad[0] + 1);
  }
  for (size_t i = 0; i < n; ++i) {
    const std::vector<int>& axis = scene.lines[i];
    ASSERT_EQ(axis.size(), 2u);
    const ToolPose& pose = path_.poses[i];
    EXPECT_LT((scene.points_w[axis[0]] - pose.p_w_tip).norm(), 1e-12);
    EXPECT_NEAR((scene.points_w[axis[1]] - pose.p_w_tip).dot(pose.a_w), 30.0, 1e-9);
    EXPECT_EQ(part[axis[0]], kTipPart);
    EXPECT_EQ(part[axis[1]], kAxisEndPart);
    EXPECT_EQ(scene.lines.back()[i], axis[0]);  // the tip path runs through the tips
  }
}

TEST_F(VtkSceneTest, WithoutASurfaceOnlyTheToolIsShown) {
  const PolyData scene = BuildPathScene(path_, cutter_, nullptr, grid_);
  EXPECT_EQ(scene.points_w.size(), 2 * path_.poses.size());
  EXPECT_TRUE(scene.polys.empty());
  EXPECT_EQ(scene.lines.size(), path_.poses.size() + 1);
}

}  // namespace
}  // namespace tpopt
