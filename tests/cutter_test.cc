#include "model/cutter/cutter.h"

#include <gtest/gtest.h>

namespace tpopt {
namespace {

double Sd(const Cutter& c, const Eigen::Vector3d& q) {
  return SignedDistanceToCutter<double>(c, q, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
}

TEST(CutterTest, WallDeviationInsideTheFluteRangeIsRadial) {
  const Cutter c{4.0, 20.0, 0.0};
  EXPECT_NEAR(Sd(c, {4.5, 0, 10}), 0.5, 1e-12);
  EXPECT_NEAR(Sd(c, {0, -3.2, 10}), -0.8, 1e-12);
  // Next to the end face the gouge depth is still radial.
  EXPECT_NEAR(Sd(c, {3.9, 0, 0}), -0.1, 1e-12);
  EXPECT_NEAR(Sd(c, {3.9, 0, 20}), -0.1, 1e-12);
  // Beyond the flute: exact distance to the solid.
  EXPECT_NEAR(Sd(c, {1, 0, -2}), 2.0, 1e-12);
  EXPECT_NEAR(Sd(c, {7, 0, 24}), 5.0, 1e-12);
  EXPECT_NEAR(SignedDistanceToFlank<double>(c, {7, 0, 24}, Eigen::Vector3d::Zero(),
                                            Eigen::Vector3d::UnitZ()),
              3.0, 1e-12);
}

TEST(CutterTest, TaperGrowsTheRadiusAndMeasuresNormalToTheFlank) {
  const double taper = 5 * M_PI / 180;
  const Cutter c{2.0, 30.0, taper};
  EXPECT_NEAR(c.RadiusAt(10), 2.0 + 10 * std::tan(taper), 1e-12);
  const double r = c.RadiusAt(10) + 0.3;
  EXPECT_NEAR(Sd(c, {r, 0, 10}), 0.3 * std::cos(taper), 1e-12);
}

TEST(CutterTest, ValidationNamesTheField) {
  std::string why;
  EXPECT_TRUE(Cutter().IsValid(&why));
  EXPECT_FALSE((Cutter{-1, 10, 0}).IsValid(&why));
  EXPECT_NE(why.find("radius -1"), std::string::npos) << why;
  EXPECT_FALSE((Cutter{1, 0, 0}).IsValid(&why));
  EXPECT_NE(why.find("flute length 0"), std::string::npos) << why;
  EXPECT_FALSE((Cutter{1, 10, std::nan("")}).IsValid(&why));
}

}  // namespace
}  // namespace tpopt
