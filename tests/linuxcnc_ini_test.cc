#include "model/io/linuxcnc_ini.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "model/io/atomic_file.h"
#include "model/io/json_io.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::FileExists;
using testing::RunCommand;
using testing::SourcePath;

constexpr double kDeg = M_PI / 180.0;
constexpr char kSampleIni[] =
    "/usr/share/doc/linuxcnc/examples/sample-configs/sim/axis/vismach/5axis/"
    "table-rotary-tilting/xyzac-trt.ini";

Status ParseText(const std::string& text, Machine* m) {
  std::istringstream in(text);
  return ParseLinuxCncIni(in, "test.ini", "", m);
}

void ExpectSameMachine(const Machine& a, const Machine& b) {
  EXPECT_EQ(a.kinematics.rotary_pivot_mm, b.kinematics.rotary_pivot_mm);
  EXPECT_EQ(a.kinematics.y_offset_mm, b.kinematics.y_offset_mm);
  EXPECT_EQ(a.kinematics.z_offset_mm, b.kinematics.z_offset_mm);
  EXPECT_EQ(a.kinematics.tool_length_mm, b.kinematics.tool_length_mm);
  for (int i = 0; i < 5; ++i) {
    SCOPED_TRACE(kAxisNames[i]);
    EXPECT_DOUBLE_EQ(a.limits[i].min, b.limits[i].min);
    EXPECT_DOUBLE_EQ(a.limits[i].max, b.limits[i].max);
    EXPECT_DOUBLE_EQ(a.limits[i].max_velocity, b.limits[i].max_velocity);
    EXPECT_DOUBLE_EQ(a.limits[i].max_acceleration,
                     b.limits[i].max_acceleration);
    EXPECT_EQ(a.limits[i].max_jerk, b.limits[i].max_jerk);
  }
}

// The values as the sample INI states them (read by eye from the file):
// JOINT_0..4 and AXIS_X..C agree; `sets :y-offset 20`, `sets :z-offset 10`
// on signals netted to xyzac-trt-kins; rot-points setp 0.
TEST(LinuxCncIniTest, ReadsLinuxCncsSampleConfig) {
  if (!FileExists(kSampleIni))
    GTEST_SKIP() << "LinuxCNC's sample configs are not installed";
  Machine m;
  const Status s = ReadLinuxCncIni(kSampleIni, &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.name, "sim-xyzac-trt-kins (switchkins)");
  EXPECT_EQ(m.kinematics.y_offset_mm, 20.0);
  EXPECT_EQ(m.kinematics.z_offset_mm, 10.0);
  EXPECT_EQ(m.kinematics.rotary_pivot_mm, Eigen::Vector3d::Zero());
  EXPECT_EQ(m.kinematics.tool_length_mm, 0.0);
  const double expected[5][4] = {
      {-200, 200, 20, 300},
      {-100, 100, 20, 300},
      {-120, 120, 20, 300},
      {-100 * kDeg, 50 * kDeg, 30 * kDeg, 300 * kDeg},
      {-36000 * kDeg, 36000 * kDeg, 30 * kDeg, 300 * kDeg}};
  for (int i = 0; i < 5; ++i) {
    SCOPED_TRACE(kAxisNames[i]);
    EXPECT_DOUBLE_EQ(m.limits[i].min, expected[i][0]);
    EXPECT_DOUBLE_EQ(m.limits[i].max, expected[i][1]);
    EXPECT_DOUBLE_EQ(m.limits[i].max_velocity, expected[i][2]);
    EXPECT_DOUBLE_EQ(m.limits[i].max_acceleration, expected[i][3]);
    EXPECT_TRUE(std::isinf(m.limits[i].max_jerk));
  }
  // The hand-written machine JSON of the same sample, and the harness's
  // headless copy of the INI (setp instead of sets), give the same machine.
  Machine json;
  ASSERT_TRUE(
      ReadMachineJson(SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"),
                      &json)
          .ok());
  ExpectSameMachine(m, json);
  Machine headless;
  const Status h = ReadLinuxCncIni(
      SourcePath("benchmarks/linuxcnc/xyzac-trt.ini"), &headless);
  ASSERT_TRUE(h.ok()) << h.message();
  ExpectSameMachine(m, headless);
}

TEST(LinuxCncIniTest, TakesTheTighterOfJointAndAxisAndTheKinematicsPins) {
  Machine m;
  const Status s = ParseText(
      "[KINS]\nKINEMATICS = xyzac-trt-kins\nJOINTS = 5\n"
      "[TRAJ]\nCOORDINATES = X Y Z A C\nLINEAR_UNITS = mm\n"
      "[HAL]\n"
      "HALCMD = net :zo xyzac-trt-kins.z-offset => other.pin\n"
      "HALCMD = sets :zo 7.5\n"
      "HALCMD = setp xyzac-trt-kins.x-rot-point 1.25 # a comment\n"
      "HALCMD = setp xyzac-trt-kins.tool-offset 3\n"
      "HALCMD = setp other.y-offset 99\n"
      "[JOINT_0]\nMIN_LIMIT = -50\nMAX_LIMIT = 40\nMAX_VELOCITY = 10\n"
      "[AXIS_X]\nMIN_LIMIT = -60\nMAX_LIMIT = 30\nMAX_ACCELERATION = 200\n"
      "; comment\n[AXIS_A]\nMAX_VELOCITY = 90\n[JOINT_3]\nMAX_VELOCITY = 45\n",
      &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.name, "test.ini");
  EXPECT_EQ(m.limits[kX].min, -50.0);
  EXPECT_EQ(m.limits[kX].max, 30.0);
  EXPECT_EQ(m.limits[kX].max_velocity, 10.0);
  EXPECT_EQ(m.limits[kX].max_acceleration, 200.0);
  EXPECT_DOUBLE_EQ(m.limits[kA].max_velocity, 45 * kDeg);
  EXPECT_TRUE(std::isinf(m.limits[kY].max_velocity));
  EXPECT_EQ(m.kinematics.z_offset_mm, 7.5);
  EXPECT_EQ(m.kinematics.rotary_pivot_mm.x(), 1.25);
  EXPECT_EQ(m.kinematics.tool_length_mm, 3.0);
  EXPECT_EQ(m.kinematics.y_offset_mm,
            0.0);  // other.y-offset is not the kinematics' pin
}

TEST(LinuxCncIniTest, ReadsSetpFromAPlainHalFile) {
  const std::string dir = std::string(TPOPT_BUILD_DIR) + "/linuxcnc_ini_test";
  ASSERT_EQ(RunCommand("mkdir -p " + dir).exit_code, 0);
  ASSERT_TRUE(WriteFileAtomically(dir + "/kins.hal",
                                  "setp xyzac-trt-kins.y-offset 12.5\n")
                  .ok());
  ASSERT_TRUE(
      WriteFileAtomically(dir + "/m.ini",
                          "[KINS]\nKINEMATICS = xyzac-trt-kins\n[HAL]\n"
                          "HALFILE = LIB:basic_sim.tcl -no_sim_spindle\n"
                          "HALFILE = kins.hal\n")
          .ok());
  Machine m;
  const Status s = ReadLinuxCncIni(dir + "/m.ini", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.kinematics.y_offset_mm, 12.5);
  ASSERT_TRUE(WriteFileAtomically(dir + "/m.ini",
                                  "[KINS]\nKINEMATICS = xyzac-trt-kins\n[HAL]\n"
                                  "HALFILE = missing.hal\n")
                  .ok());
  const Status missing = ReadLinuxCncIni(dir + "/m.ini", &m);
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("m.ini:4: [HAL] HALFILE = missing.hal"),
            std::string::npos)
      << missing.message();
}

TEST(LinuxCncIniTest, BadInputNamesTheLineAndTheValue) {
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"[KINS]\nKINEMATICS = xyzac-trt-kins\n[JOINT_2]\nMAX_VELOCITY = fast\n",
       "test.ini:4: [JOINT_2] MAX_VELOCITY = 'fast' is not a number"},
      {"[KINS]\nKINEMATICS = xyzac-trt-kins\n[AXIS_C]\nMAX_ACCELERATION = 0\n",
       "test.ini:4: [AXIS_C] MAX_ACCELERATION = 0 must be > 0"},
      {"[KINS]\nKINEMATICS = trivkins\n",
       "test.ini:2: [KINS] KINEMATICS = trivkins"},
      {"[EMC]\nMACHINE = x\n", "[KINS] KINEMATICS is missing"},
      {"[KINS]\nKINEMATICS = xyzac-trt-kins\n[TRAJ]\nLINEAR_UNITS = inch\n",
       "test.ini:4: [TRAJ] LINEAR_UNITS = inch: only mm"},
      {"[KINS]\nKINEMATICS = xyzac-trt-kins\n[JOINT_1]\nMIN_LIMIT = "
       "5\n[AXIS_Y]\nMAX_LIMIT = 4\n",
       "axis Y: MIN_LIMIT 5 is above MAX_LIMIT 4"},
      {"[KINS]\nKINEMATICS = xyzac-trt-kins\n[HAL]\nHALCMD = setp "
       "xyzac-trt-kins.y-offset x1\n",
       "test.ini:4: setp xyzac-trt-kins.y-offset = 'x1' is not a number"},
      {"[KINS\n", "test.ini:1: section header '[KINS' has no ']'"},
  };
  for (const Case& c : cases) {
    Machine m;
    m.name = "untouched";
    const Status s = ParseText(c.text, &m);
    ASSERT_FALSE(s.ok()) << c.text;
    EXPECT_NE(s.message().find(c.message), std::string::npos) << s.message();
    EXPECT_EQ(m.name, "untouched");
  }
}

TEST(LinuxCncIniTest, RecognisesIniNames) {
  EXPECT_TRUE(IsLinuxCncIni("a/xyzac-trt.ini"));
  EXPECT_TRUE(IsLinuxCncIni("M.INI"));
  EXPECT_FALSE(IsLinuxCncIni("machine.json"));
  EXPECT_FALSE(IsLinuxCncIni("ini"));
}

}  // namespace
}  // namespace tpopt
