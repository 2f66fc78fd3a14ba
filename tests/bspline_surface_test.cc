// The tensor-product surface against exact polynomials: a bicubic Bezier
// patch that is the function z = x^2 y, a multi-span surface that is a
// plane (linear precision at the Greville abscissae), and the JSON reader.
#include "model/geometry/bspline_surface.h"

#include <fstream>

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::SourcePath;
using testing::TempDir;

// Greville abscissae of a cubic knot vector.
std::vector<double> Greville(const std::vector<double>& knots) {
  std::vector<double> g;
  for (size_t i = 0; i + 4 < knots.size(); ++i) g.push_back((knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3);
  return g;
}

TEST(BSplineSurfaceTest, BicubicPatchReproducesAPolynomialAndItsPartials) {
  // x = 40 u, y = 30 v, z = u^2 v: the cubic Bernstein coefficients of u^2
  // are its blossom (u1 u2 + u1 u3 + u2 u3) / 3 at (0,0,0), (0,0,1),
  // (0,1,1), (1,1,1) = 0, 0, 1/3, 1; those of v are 0, 1/3, 2/3, 1.
  const double u2[4] = {0, 0, 1.0 / 3, 1}, lin[4] = {0, 1.0 / 3, 2.0 / 3, 1};
  std::vector<std::vector<Eigen::Vector3d>> net(4, std::vector<Eigen::Vector3d>(4));
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) net[i][j] = {40 * lin[i], 30 * lin[j], u2[i] * lin[j]};
  }
  BSplineSurface s;
  ASSERT_TRUE(BSplineSurface::Create(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {5, 5, 5, 5, 7, 7, 7, 7},
                                     net, "patch", &s)
                  .ok());
  for (double u : {0.0, 0.3, 0.71, 1.0}) {
    for (double v : {0.0, 0.5, 0.9, 1.0}) {
      const SurfacePoint p = s.Evaluate(u, v);
      EXPECT_LT((p.point - Eigen::Vector3d(40 * u, 30 * v, u * u * v)).norm(), 1e-12);
      EXPECT_LT((p.du - Eigen::Vector3d(40, 0, 2 * u * v)).norm(), 1e-11);
      EXPECT_LT((p.dv - Eigen::Vector3d(0, 30, u * u)).norm(), 1e-11);
      EXPECT_LT((p.duu - Eigen::Vector3d(0, 0, 2 * v)).norm(), 1e-10);
      EXPECT_LT((p.duv - Eigen::Vector3d(0, 0, 2 * u)).norm(), 1e-10);
      EXPECT_LT(p.dvv.norm(), 1e-10);
      const Eigen::Vector3d n = Eigen::Vector3d(40, 0, 2 * u * v).cross(Eigen::Vector3d(0, 30, u * u));
      EXPECT_LT((p.UnitNormal() - n.normalized()).norm(), 1e-12);
    }
  }
}

TEST(BSplineSurfaceTest, MultiSpanSurfaceOfAPlaneIsThatPlane) {
  const std::vector<double> ku = {0, 0, 0, 0, 0.2, 0.5, 0.6, 1, 1, 1, 1};
  const std::vector<double> kv = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
  const std::vector<double> gu = Greville(ku), gv = Greville(kv);
  auto plane = [](double x, double y) { return 3.0 + 0.5 * x - 0.25 * y; };
  std::vector<std::vector<Eigen::Vector3d>> net(gu.size(), std::vector<Eigen::Vector3d>(gv.size()));
  for (size_t i = 0; i < gu.size(); ++i) {
    for (size_t j = 0; j < gv.size(); ++j) {
      net[i][j] = {100 * gu[i], 50 * gv[j], plane(100 * gu[i], 50 * gv[j])};
    }
  }
  BSplineSurface s;
  ASSERT_TRUE(BSplineSurface::Create(3, 3, ku, kv, net, "plane", &s).ok());
  const Eigen::Vector3d normal = Eigen::Vector3d(-0.5, 0.25, 1).normalized();
  for (double u = 0; u <= 1.0; u += 0.0625) {
    for (double v = 0; v <= 1.0; v += 0.125) {
      const SurfacePoint p = s.Evaluate(u, v);
      EXPECT_NEAR(p.point.x(), 100 * u, 1e-11);
      EXPECT_NEAR(p.point.y(), 50 * v, 1e-11);
      EXPECT_NEAR(p.point.z(), plane(100 * u, 50 * v), 1e-11);
      EXPECT_LT((p.UnitNormal() - normal).norm(), 1e-12);
      EXPECT_LT(p.duu.norm() + p.duv.norm() + p.dvv.norm(), 1e-8);
    }
  }
}

TEST(BSplineSurfaceTest, RejectsRaggedNetsAndBadKnotsNamingTheField) {
  std::vector<std::vector<Eigen::Vector3d>> net(4, std::vector<Eigen::Vector3d>(4, Eigen::Vector3d::Zero()));
  BSplineSurface s;
  auto ragged = net;
  ragged[2].pop_back();
  Status st = BSplineSurface::Create(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1},
                                     ragged, "f.json", &s);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("control_points[2]"), std::string::npos) << st.message();
  st = BSplineSurface::Create(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 1, 1, 1, 1, 1}, net,
                              "f.json", &s);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("knots_v"), std::string::npos) << st.message();
  st = BSplineSurface::Create(4, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, net,
                              "f.json", &s);
  EXPECT_FALSE(st.ok());
  net[1][3].y() = NAN;
  st = BSplineSurface::Create(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, net,
                              "f.json", &s);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("control_points[1][3]"), std::string::npos) << st.message();
}

TEST(BSplineSurfaceJsonTest, ReadsTheBundledSurfaceAndItsStatedSize) {
  BSplineSurface s;
  const Status st = ReadBSplineSurfaceJson(SourcePath("data/pencil/surface_120x120x55.json"), &s);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(s.degree_u(), 3);
  EXPECT_EQ(s.degree_v(), 3);
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i <= 60; ++i) {
    for (int j = 0; j <= 60; ++j) {
      const Eigen::Vector3d p = s.Point(i / 60.0, j / 60.0);
      // Greville placement makes x and y linear in u and v.
      EXPECT_NEAR(p.x(), 2.0 * i, 1e-9);
      EXPECT_NEAR(p.y(), 2.0 * j, 1e-9);
      lo = std::min(lo, p.z());
      hi = std::max(hi, p.z());
    }
  }
  EXPECT_NEAR(hi - lo, 55.0, 1e-6);
}

TEST(BSplineSurfaceJsonTest, ErrorsNameTheFileAndTheField) {
  TempDir dir;
  const std::string path = dir.File("s.json");
  const std::string head =
      R"({"kind": "bspline_surface", "degree_u": 1, "degree_v": 1, "knots_u": [0, 0, 1, 1], )";
  struct Case {
    std::string body, expect;
  };
  const Case cases[] = {
      {head + R"("knots_v": [0, 0, 1, 1], "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,"x"]]]})",
       "control_points[1][1][2]"},
      {head + R"("knots_v": [0, 0, 1], "control_points": [[[0,0,0],[0,1,0]],[[1,0,0],[1,1,0]]]})",
       "knots_v"},
      {R"({"kind": "ruled"})", "kind \"ruled\""},
      {head + R"("control_points": []})", "knots_v must be an array"},
      {"{\"kind\": \n[", ":2: malformed JSON"},
  };
  for (const Case& c : cases) {
    std::ofstream(path) << c.body;
    BSplineSurface s;
    const Status st = ReadBSplineSurfaceJson(path, &s);
    ASSERT_FALSE(st.ok()) << c.body;
    EXPECT_NE(st.message().find(path), std::string::npos) << st.message();
    EXPECT_NE(st.message().find(c.expect), std::string::npos) << st.message();
  }
}

}  // namespace
}  // namespace tpopt
