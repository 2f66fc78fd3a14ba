#include "model/io/json_io.h"

#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace tpopt {
namespace {

constexpr double kDeg = M_PI / 180.0;

class JsonIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/tpopt_json_XXXXXX";
    dir_ = mkdtemp(pattern);
  }
  void TearDown() override { std::system(("rm -rf " + dir_).c_str()); }

  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path) << text;
    return path;
  }

  // The message of a failed read, or "" if it succeeded.
  std::string SurfaceError(const std::string& text) {
    RuledSurface s;
    const Status st = ReadSurfaceJson(Write("s.json", text), &s);
    return st.ok() ? "" : st.message();
  }
  std::string MachineError(const std::string& text) {
    Machine m;
    const Status st = ReadMachineJson(Write("m.json", text), &m);
    return st.ok() ? "" : st.message();
  }

  std::string dir_;
};

TEST_F(JsonIoTest, ReadsTheSharedSurfaces) {
  RuledSurface s;
  ASSERT_TRUE(ReadSurfaceJson(testing::SourcePath("data/surfaces/jcde2022.json"), &s).ok());
  EXPECT_EQ(s.name(), "jcde2022");
  EXPECT_EQ(s.rail(0).degree(), 3);
  EXPECT_LT((s.Point(0, 0) - Eigen::Vector3d(5, 0, 0)).norm(), 1e-12);
  EXPECT_LT((s.Point(1, 1) - Eigen::Vector3d(60, 0, 15)).norm(), 1e-12);
  ASSERT_TRUE(ReadSurfaceJson(testing::SourcePath("data/surfaces/impeller_blade.json"), &s).ok());
  EXPECT_LT((s.Point(0, 1) - Eigen::Vector3d(34, 0, 46)).norm(), 1e-12);
  EXPECT_EQ(s.cutter_side(), CutterSide::kPositive);
}

TEST_F(JsonIoTest, ReadsTheSharedMachinesInRadians) {
  Machine m;
  ASSERT_TRUE(
      ReadMachineJson(testing::SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"), &m).ok());
  EXPECT_EQ(m.kinematics.y_offset_mm, 20);
  EXPECT_EQ(m.kinematics.z_offset_mm, 10);
  EXPECT_NEAR(m.limits[kA].min, -100 * kDeg, 1e-12);
  EXPECT_NEAR(m.limits[kA].max, 50 * kDeg, 1e-12);
  EXPECT_NEAR(m.limits[kC].max_velocity, 30 * kDeg, 1e-12);
  EXPECT_EQ(m.limits[kX].max_velocity, 20);
  EXPECT_TRUE(std::isinf(m.limits[kX].max_jerk));
  ASSERT_TRUE(ReadMachineJson(testing::SourcePath("data/machines/jcde2022_ac.json"), &m).ok());
  EXPECT_NEAR(m.limits[kA].max_jerk, 85.943669 * kDeg, 1e-9);
  EXPECT_TRUE(std::isinf(m.limits[kC].min));
}

TEST_F(JsonIoTest, BadSurfacesNameFileAndPlace) {
  RuledSurface s;
  Status st = ReadSurfaceJson(dir_ + "/missing.json", &s);
  EXPECT_NE(st.message().find("missing.json: cannot open"), std::string::npos) << st.message();
  std::string e = SurfaceError("{\"rails\": [\n{\"degree\": 1,,}]}");
  EXPECT_NE(e.find("s.json:2: malformed JSON"), std::string::npos) << e;
  const std::string rail =
      "{\"degree\": 1, \"knots\": [0, 0, 1, 1], \"control_points\": [[0,0,0],[1,0,0]]}";
  e = SurfaceError("{\"rails\": [" + rail + "]}");
  EXPECT_NE(e.find("exactly two"), std::string::npos) << e;
  e = SurfaceError("{\"rails\": [" + rail +
                   ", {\"degree\": 1, \"knots\": [0, 0, 1], \"control_points\": [[0,0,1],[1,0,1]]}]}");
  EXPECT_NE(e.find("rails[1]: 3 knots"), std::string::npos) << e;
  e = SurfaceError("{\"rails\": [" + rail +
                   ", {\"degree\": 1, \"knots\": [0, 0.5, 0.2, 1, 1], \"control_points\": "
                   "[[0,0,1],[1,0,1],[2,0,1]]}]}");
  EXPECT_NE(e.find("rails[1]: knots decrease at index 2"), std::string::npos) << e;
  e = SurfaceError("{\"rails\": [" + rail +
                   ", {\"degree\": 1, \"knots\": [0, 0, 1, 1], \"control_points\": "
                   "[[0,0,1],[1,\"x\",1]]}]}");
  EXPECT_NE(e.find("control_points[1][1] must be a number"), std::string::npos) << e;
  e = SurfaceError("{\"rails\": [" + rail +
                   ", {\"degree\": 1, \"knots\": [0, 0, 1, 1], \"control_points\": "
                   "[[0,0,1],[1e308,0,1]]}]}");
  EXPECT_NE(e.find("control_points[1][0] = 1e+308 is out of range"), std::string::npos) << e;
  // Found by the fuzzer: a number where a string belongs once escaped as an
  // exception.
  e = SurfaceError("{\"kind\": 3, \"rails\": []}");
  EXPECT_NE(e.find("s.json: surface.kind must be a string, got 3"), std::string::npos) << e;
  e = MachineError("{\"kinematics\": [1]}");
  EXPECT_NE(e.find("m.json: machine.kinematics must be a string"), std::string::npos) << e;
  e = SurfaceError("{\"kind\": \"nurbs\", \"rails\": []}");
  EXPECT_NE(e.find("kind \"nurbs\""), std::string::npos) << e;
  e = SurfaceError("{\"cutter_side\": \"left\", \"rails\": [" + rail + "," + rail + "]}");
  EXPECT_NE(e.find("cutter_side \"left\""), std::string::npos) << e;
  // Rails of different degree are fine: the surface is defined rail by rail.
  const std::string cubic =
      "{\"degree\": 3, \"knots\": [0,0,0,0,1,1,1,1], \"control_points\": "
      "[[0,0,5],[1,1,5],[2,1,5],[3,0,5]]}";
  EXPECT_EQ(SurfaceError("{\"rails\": [" + rail + "," + cubic + "]}"), "");
}

TEST_F(JsonIoTest, BadMachinesNameFileKeyAndValue) {
  std::string e = MachineError("{\"kinematics\": \"xyzbc-trt\"}");
  EXPECT_NE(e.find("m.json: kinematics \"xyzbc-trt\""), std::string::npos) << e;
  e = MachineError("{\"kinematics\": \"xyzac-trt\", \"axes\": {\"A\": {\"max_velocity\": -3}}}");
  EXPECT_NE(e.find("axes.A"), std::string::npos) << e;
  EXPECT_NE(e.find("-3"), std::string::npos) << e;
  e = MachineError("{\"kinematics\": \"xyzac-trt\", \"axes\": {\"X\": {\"min\": 5, \"max\": 1}}}");
  EXPECT_NE(e.find("axes.X: min 5 is above max 1"), std::string::npos) << e;
  e = MachineError("{\"kinematics\": \"xyzac-trt\", \"axes\": {\"B\": {}}}");
  EXPECT_NE(e.find("axes.B"), std::string::npos) << e;
  e = MachineError("{\"kinematics\": \"xyzac-trt\", \"y_offset\": \"twenty\"}");
  EXPECT_NE(e.find("y_offset must be a number"), std::string::npos) << e;
  e = MachineError("{\"kinematics\": \"xyzac-trt\", \"rotary_pivot\": [0, 1]}");
  EXPECT_NE(e.find("rotary_pivot must be [x, y, z]"), std::string::npos) << e;
  e = MachineError("{\"kinematics\": \"xyzac-trt\", \"axes\": {\"Z\": {\"max_jerk\": 1e999}}}");
  EXPECT_NE(e.find("m.json"), std::string::npos) << e;
}

}  // namespace
}  // namespace tpopt
