// `tpopt stripwidth` end to end: a pass on the propeller blade, its report,
// its APT path through `tpopt smooth` without a surface, and bad input.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::FileExists;
using testing::ReadJson;
using testing::RunCommand;
using testing::SourcePath;
using testing::TempDir;
using testing::Tpopt;

const std::string kBlade = SourcePath("data/surfaces/propeller_blade_freeform.json");
const std::string kMachine = SourcePath("data/machines/jcde2022_ac.json");

std::string StripWidth(const std::string& method, const TempDir& dir, const std::string& extra) {
  return Tpopt("stripwidth --surface=" + kBlade + " --method=" + method +
               " --cutter=torus:8,2 --tolerance_mm=0.01 --cc_points=6 --machine=" + kMachine +
               " --out=" + dir.File(method + ".cls") + " --report=" + dir.File(method + ".json") +
               " " + extra);
}

TEST(StripWidthCliTest, WritesAPathAndReportThatSmoothTakesWithoutASurface) {
  TempDir dir;
  for (const std::string method : {"sturz", "mpec"}) {
    const auto r = RunCommand(StripWidth(method, dir, ""));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json j = ReadJson(dir.File(method + ".json"));
    ASSERT_EQ(j["cc_points"].size(), 6u);
    for (const auto& p : j["cc_points"]) {
      EXPECT_GT(p["width_mm"].get<double>(), 0.5) << method;
      EXPECT_LE(p["max_deviation_in_strip_mm"].get<double>(), 0.01 + 1e-9) << method;
      EXPECT_GE(p["min_deviation_mm"].get<double>(), -1e-6) << method;
    }
    EXPECT_GT(j["strips"]["centre_fluctuation_max_mm"].get<double>(), 0.0);
    EXPECT_TRUE(j["A"].contains("peak_second_derivative_per_mm2")) << j.dump();
  }
  // Sturz keeps its lead; MPEC centres its strips on the CC points.
  // Held in a variable: a range-for over a member of a temporary would read
  // freed memory.
  const nlohmann::json sturz = ReadJson(dir.File("sturz.json"));
  for (const auto& p : sturz["cc_points"]) {
    EXPECT_NEAR(p["lead_deg"].get<double>(), 10.0, 1e-9);
  }
  EXPECT_LT(ReadJson(dir.File("mpec.json"))["strips"]["max_strip_mid_offset_mm"].get<double>(),
            0.2);
  const auto r = RunCommand(Tpopt("smooth --in=" + dir.File("mpec.cls") + " --out=" +
                                  dir.File("s.cls") + " --machine=" + kMachine +
                                  " --mode=high_accuracy --report=" + dir.File("r.json")));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(ReadJson(dir.File("r.json"))["poses_out"], 6);
}

TEST(StripWidthCliTest, BadInputFailsCleanlyAndWritesNothing) {
  TempDir dir;
  // Usage: the corner radius exceeds the radius; an unknown method.
  auto r = RunCommand(StripWidth("sturz", dir, "--cutter=torus:2,8"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("r = 8"), std::string::npos) << r.output;
  r = RunCommand(StripWidth("zigzag", dir, ""));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--method=zigzag"), std::string::npos) << r.output;
  // Bad input: a surface whose control net has a short row.
  std::ifstream in(kBlade);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json surface = nlohmann::json::parse(text.str());
  surface["control_points"][3].erase(0);
  const std::string bad = dir.File("bad.json");
  std::ofstream(bad) << surface.dump();
  r = RunCommand(Tpopt("stripwidth --surface=" + bad + " --method=sturz --cutter=torus:8,2 --out=" +
                       dir.File("x.cls")));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find(bad + ": control_points[3] has 6 points"), std::string::npos)
      << r.output;
  EXPECT_FALSE(FileExists(dir.File("x.cls")));
  EXPECT_FALSE(FileExists(dir.File("sturz.cls")));
  EXPECT_FALSE(FileExists(dir.File("zigzag.cls")));
}

}  // namespace
}  // namespace tpopt
