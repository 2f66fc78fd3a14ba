#include "model/geometry/segment_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace tpopt {
namespace {

TEST(DistanceToSegmentTest, FootInsideIsThePerpendicularDistance) {
  const Eigen::Vector3d a(0, 0, 0), b(10, 0, 0);
  EXPECT_DOUBLE_EQ(DistanceToSegment(Eigen::Vector3d(4, 3, 4), a, b), 5.0);
}

TEST(DistanceToSegmentTest, BeyondAnEndIsTheDistanceToThatEnd) {
  const Eigen::Vector3d a(0, 0, 0), b(10, 0, 0);
  EXPECT_DOUBLE_EQ(DistanceToSegment(Eigen::Vector3d(-3, 4, 0), a, b), 5.0);
  EXPECT_DOUBLE_EQ(DistanceToSegment(Eigen::Vector3d(13, 0, 4), a, b), 5.0);
}

TEST(DistanceToSegmentTest, DegenerateSegmentIsAPoint) {
  const Eigen::Vector3d a(1, 2, 3);
  EXPECT_DOUBLE_EQ(DistanceToSegment(Eigen::Vector3d(1, 2, 8), a, a), 5.0);
}

// Against the best of 20001 points on the segment, at random, both ways
// round: the minimum over the samples is within the sample spacing.
TEST(DistanceToSegmentTest, MatchesBruteForceAndIsSymmetricInTheEnds) {
  std::mt19937 rng(20);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  auto random_point = [&] {
    return Eigen::Vector3d(coord(rng), coord(rng), coord(rng));
  };
  for (int draw = 0; draw < 50; ++draw) {
    const Eigen::Vector3d a = random_point(), b = random_point(),
                          q = random_point();
    constexpr int kSamples = 20000;
    double best = 1e300;
    for (int i = 0; i <= kSamples; ++i) {
      const double t = static_cast<double>(i) / kSamples;
      best = std::min(best, (a + t * (b - a) - q).norm());
    }
    const double d = DistanceToSegment(q, a, b);
    EXPECT_LE(d, best + 1e-12) << "draw " << draw;
    EXPECT_NEAR(d, best, (b - a).norm() / kSamples) << "draw " << draw;
    EXPECT_NEAR(DistanceToSegment(q, b, a), d, 1e-12) << "draw " << draw;
  }
}

}  // namespace
}  // namespace tpopt
