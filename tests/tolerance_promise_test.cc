#include "solver/smooth/tolerance_promise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace tpopt {
namespace {

// A grid of nu x nv points, u uniform on [0, 1], every deviation `value`.
DeviationReport Grid(int nu, int nv, double value) {
  DeviationReport r;
  for (int i = 0; i < nu; ++i) r.u.push_back(static_cast<double>(i) / (nu - 1));
  for (int j = 0; j < nv; ++j) r.v.push_back(static_cast<double>(j) / (nv - 1));
  r.deviation_mm.assign(r.u.size() * r.v.size(), value);
  return r;
}

// The CAM path touched the surface at one grid point (u 0.5, v 0) between
// poses whose moves leave 0.5 mm all round it: no smooth path can keep that
// one point, and the promise does not ask it to. Where the input held the
// tolerance across the whole move, it does.
TEST(TolerancePromiseTest, ALuckyPointBetweenPosesFarOffPromisesNothing) {
  DeviationReport in = Grid(11, 3, 0.5);
  in.deviation_mm[5 * 3 + 0] = 0.001;  // u 0.5, v 0
  const std::vector<double> poses_u = {0.0, 0.35, 0.65, 1.0};
  const std::vector<double> allowance = InputAllowance(in, poses_u);
  EXPECT_DOUBLE_EQ(allowance[5 * 3 + 0], 0.5);

  DeviationReport out = Grid(11, 3, 0.005);
  out.deviation_mm[5 * 3 + 0] = -0.012;  // beyond 0.01, within the input's 0.5 there
  EXPECT_TRUE(BeyondTolerance(allowance, out, 0.01).empty());
  out.deviation_mm[5 * 3 + 0] = -0.6;  // beyond the input's worst over the move
  EXPECT_EQ(BeyondTolerance(allowance, out, 0.01), std::vector<size_t>{5 * 3 + 0});

  // The same point where the input held 0.001 across the move (u 0.35 to
  // 0.65: grid points 4, 5 and 6) is held to the tolerance.
  for (int iu = 4; iu <= 6; ++iu) in.deviation_mm[iu * 3 + 0] = 0.001;
  const std::vector<double> held = InputAllowance(in, poses_u);
  EXPECT_DOUBLE_EQ(held[5 * 3 + 0], 0.001);
  out.deviation_mm[5 * 3 + 0] = -0.012;
  EXPECT_EQ(BeyondTolerance(held, out, 0.01), std::vector<size_t>{5 * 3 + 0});
  // Within the tolerance is never beyond, whatever the input.
  out.deviation_mm[5 * 3 + 0] = 0.0099;
  EXPECT_TRUE(BeyondTolerance(held, out, 0.01).empty());
}

// Against brute force on random grids: each point's allowance is the worst
// |input| over the grid points of its v from the ruling of the last pose
// below it to the first above (both sides at a pose's own ruling), and from
// the nearest pose to itself beyond the poses' range.
TEST(TolerancePromiseTest, AllowanceIsTheInputsWorstAcrossTheMoveAgainstBruteForce) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    DeviationReport in = Grid(21, 4, 0.0);
    for (double& d : in.deviation_mm) d = (unit(rng) - 0.5) * 0.2;
    std::vector<double> poses_u;
    const int poses = 2 + trial % 7;
    for (int k = 0; k < poses; ++k) {
      // Some poses on grid rulings exactly, some between, some inside only.
      poses_u.push_back(k % 3 == 0 ? in.u[static_cast<size_t>(unit(rng) * 20.999)]
                                   : 0.1 + 0.8 * unit(rng));
    }
    const std::vector<double> allowance = InputAllowance(in, poses_u);
    const size_t nv = in.v.size();
    for (size_t iu = 0; iu < in.u.size(); ++iu) {
      const double u = in.u[iu];
      double lo = -INFINITY, hi = INFINITY, least = INFINITY, most = -INFINITY;
      for (double p : poses_u) {
        if (p < u) lo = std::max(lo, p);
        if (p > u) hi = std::min(hi, p);
        least = std::min(least, p);
        most = std::max(most, p);
      }
      if (!std::isfinite(lo)) lo = std::min(u, least);
      if (!std::isfinite(hi)) hi = std::max(u, most);
      for (size_t iv = 0; iv < nv; ++iv) {
        double worst = 0.0;
        for (size_t ju = 0; ju < in.u.size(); ++ju) {
          if (in.u[ju] >= lo && in.u[ju] <= hi) {
            worst = std::max(worst, std::abs(in.deviation_mm[ju * nv + iv]));
          }
        }
        ASSERT_DOUBLE_EQ(allowance[iu * nv + iv], worst)
            << "trial " << trial << " u " << u << " v " << in.v[iv];
      }
    }
  }
}

TEST(TolerancePromiseTest, WithoutPosesNothingIsAllowed) {
  const DeviationReport in = Grid(5, 2, 0.3);
  const std::vector<double> allowance = InputAllowance(in, {});
  ASSERT_EQ(allowance.size(), in.deviation_mm.size());
  for (double a : allowance) EXPECT_EQ(a, 0.0);
}

// A tolerance round that held the points beyond harder and moved none of
// them by more than a nanometre has stalled; one that moved any of them,
// or left others beyond, has not.
TEST(TolerancePromiseTest, SameBeyondPointsOnlyWhereNoneMoved) {
  DeviationReport before = Grid(5, 2, 0.001);
  before.deviation_mm[3] = 0.013;
  before.deviation_mm[6] = -0.0121;
  const std::vector<double> allowance(before.deviation_mm.size(), 0.0);
  const std::vector<size_t> beyond_before = BeyondTolerance(allowance, before, 0.01);
  ASSERT_EQ(beyond_before, (std::vector<size_t>{3, 6}));

  DeviationReport after = before;
  after.deviation_mm[0] = 0.002;  // a point within the tolerance moved
  after.deviation_mm[6] -= 0.5e-6;
  EXPECT_TRUE(SameBeyondPoints(before, beyond_before, after,
                               BeyondTolerance(allowance, after, 0.01), 1e-6));

  after.deviation_mm[6] -= 1e-6;  // now 1.5 nm farther
  EXPECT_FALSE(SameBeyondPoints(before, beyond_before, after,
                                BeyondTolerance(allowance, after, 0.01), 1e-6));

  after = before;
  after.deviation_mm[6] = 0.009;  // brought within
  EXPECT_FALSE(SameBeyondPoints(before, beyond_before, after,
                                BeyondTolerance(allowance, after, 0.01), 1e-6));

  after = before;
  after.deviation_mm[8] = 0.02;  // another pushed out
  EXPECT_FALSE(SameBeyondPoints(before, beyond_before, after,
                                BeyondTolerance(allowance, after, 0.01), 1e-6));

  // Nothing beyond before (the first round) or after (held).
  EXPECT_FALSE(SameBeyondPoints(before, {}, before, beyond_before, 1e-6));
  EXPECT_FALSE(SameBeyondPoints(before, beyond_before, Grid(5, 2, 0.001), {}, 1e-6));
}

}  // namespace
}  // namespace tpopt
