#include "model/path/part_setup.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tpopt {
namespace {

TEST(PartSetupTest, RotationIsZAfterYAfterXAboutFixedAxes) {
  PartSetup setup;
  setup.rotation_deg = Eigen::Vector3d(0, 0, 90);
  // +90 deg about Z takes +X to +Y.
  EXPECT_LT((setup.Rotation() * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 1e-15);
  // X first, then Z: (rx, rz) = (90, 90) takes +Y to +Z (by X) and keeps it.
  setup.rotation_deg = Eigen::Vector3d(90, 0, 90);
  EXPECT_LT((setup.Rotation() * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
  // ... and +Z to -Y (by X), then to +X (by Z).
  EXPECT_LT((setup.Rotation() * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(), 1e-15);
}

TEST(PartSetupTest, PlaceThenUnplaceIsTheIdentityAndPlacesTheOrigin) {
  PartSetup setup;
  ASSERT_TRUE(ParsePartSetup("120,-5.5,-35,10,-20,30", &setup).ok());
  ToolPath path;
  ToolPose pose;
  pose.p_w_tip = Eigen::Vector3d::Zero();  // the part's origin
  path.poses.push_back(pose);
  pose.p_w_tip = Eigen::Vector3d(10, 20, 30);
  pose.a_w = Eigen::Vector3d(0.6, 0, 0.8);
  path.poses.push_back(pose);
  ToolPath placed = path;
  PlacePart(setup, &placed);
  EXPECT_LT((placed.poses[0].p_w_tip - Eigen::Vector3d(120, -5.5, -35)).norm(), 1e-12);
  // Distances and the angle between tip offset and axis are kept (rigid).
  EXPECT_NEAR((placed.poses[1].p_w_tip - placed.poses[0].p_w_tip).norm(),
              Eigen::Vector3d(10, 20, 30).norm(), 1e-12);
  EXPECT_NEAR(placed.poses[1].a_w.norm(), 1.0, 1e-15);
  EXPECT_NEAR(placed.poses[1].a_w.dot(placed.poses[1].p_w_tip - placed.poses[0].p_w_tip),
              pose.a_w.dot(pose.p_w_tip), 1e-12);
  ToolPath back = placed;
  UnplacePart(setup, &back);
  for (size_t i = 0; i < path.poses.size(); ++i) {
    EXPECT_LT((back.poses[i].p_w_tip - path.poses[i].p_w_tip).norm(), 1e-12);
    EXPECT_LT((back.poses[i].a_w - path.poses[i].a_w).norm(), 1e-15);
    EXPECT_LT((UnplacePoint(setup, placed.poses[i].p_w_tip) - path.poses[i].p_w_tip).norm(), 1e-12);
  }
}

TEST(PartSetupTest, ParseRefusesWhatIsNotSixNumbersInRange) {
  PartSetup setup;
  for (const char* bad : {"", "1,2,3", "1,2,3,4,5,6,7", "1,2,3,4,5,x", "1,2,3,4,5,6,"}) {
    const Status s = ParsePartSetup(bad, &setup);
    ASSERT_FALSE(s.ok()) << bad;
    EXPECT_NE(s.message().find("must be tx,ty,tz,rx,ry,rz"), std::string::npos) << s.message();
  }
  const Status s = ParsePartSetup("0,0,0,0,400,0", &setup);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("ry = 400 deg must be finite and within +-360"), std::string::npos)
      << s.message();
  EXPECT_FALSE(ParsePartSetup("nan,0,0,0,0,0", &setup).ok());
}

}  // namespace
}  // namespace tpopt
