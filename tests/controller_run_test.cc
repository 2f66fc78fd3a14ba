#include "apps/controller_run.h"

#include <string>

#include <gtest/gtest.h>

#include "model/io/atomic_file.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::TempDir;

// A summary as benchmarks/linuxcnc/analyze.py writes it (fields it has
// that the reader does not use left out).
std::string Summary(const std::string& c_cuts) {
  return R"({"program": "/tmp/p.ngc", "completed": true, "cycle_time_s": 27.142,
  "stops_in_cuts": 2, "limit_excess": [{"joint": "Z"}, {"joint": "Y"}, {"joint": "X"}],
  "joints": {"A": {"cuts": {"acceleration": {"peak": 151.0, "p99": 61.0},
                             "jerk": {"peak": 89000.0, "p99": 13000.0}}},
             "C": {"cuts": )" +
         c_cuts + "}}}";
}

TEST(ControllerRunTest, ReadsTheHarnessSummary) {
  TempDir dir;
  const std::string file = dir.File("summary.json");
  ASSERT_TRUE(WriteFileAtomically(file, Summary(R"({"acceleration": {"peak": 301.0, "p99": 146.2},
      "jerk": {"peak": 2000000.0, "p99": 18000.0}})"))
                  .ok());
  ControllerRun run;
  const Status s = ReadControllerRun(file, &run);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(run.completed);
  EXPECT_EQ(run.program, "/tmp/p.ngc");
  EXPECT_EQ(run.cycle_time_s, 27.142);
  EXPECT_EQ(run.stops_in_cuts, 2);
  EXPECT_EQ(run.limits_exceeded, 3);
  EXPECT_EQ(run.peak_acceleration[0], 151.0);
  EXPECT_EQ(run.p99_acceleration[0], 61.0);
  EXPECT_EQ(run.p99_acceleration[1], 146.2);
  EXPECT_EQ(run.peak_jerk[1], 2e6);  // no geometric range cap on a jerk
  EXPECT_EQ(run.p99_jerk[0], 13000.0);

  const nlohmann::json j = ControllerRunJson(run, 26.5);
  EXPECT_EQ(j["predicted_time_s"], 26.5);
  EXPECT_EQ(j["cycle_time_s"], 27.142);
  EXPECT_EQ(j["C"]["p99_acceleration"], 146.2);
  const std::string html = ControllerRunHtml(run, 26.5);
  EXPECT_NE(html.find("<td>cycle time on the controller, s</td><td>27.1</td>"), std::string::npos)
      << html;
  EXPECT_NE(html.find("<td>tpopt's predicted time, s</td><td>26.5</td>"), std::string::npos);
  EXPECT_NE(html.find("C acceleration in cuts, deg/s^2</td><td>301 / 146</td>"),
            std::string::npos);
}

TEST(ControllerRunTest, AFailedRunIsReadAsNotCompleted) {
  TempDir dir;
  const std::string file = dir.File("failed.json");
  ASSERT_TRUE(WriteFileAtomically(file, R"({"program": "p.ngc", "completed": false,
      "error": "RCS_ERROR at program line 12"})")
                  .ok());
  ControllerRun run;
  ASSERT_TRUE(ReadControllerRun(file, &run).ok());
  EXPECT_FALSE(run.completed);
  EXPECT_NE(ControllerRunHtml(run, 1.0).find("<td>completed</td><td>no</td>"), std::string::npos);
}

TEST(ControllerRunTest, BadSummariesNameTheFileAndTheField) {
  TempDir dir;
  const std::string file = dir.File("bad.json");
  const std::pair<std::string, std::string> cases[] = {
      {"[1, 2]", "must be a JSON object"},
      {R"({"completed": "yes"})", "completed (true or false) is missing"},
      {R"({"completed": true, "stops_in_cuts": 0})", "cycle_time_s is missing"},
      {R"({"completed": true, "cycle_time_s": "long", "stops_in_cuts": 0})",
       "cycle_time_s must be a number"},
      {Summary(R"({"acceleration": {"peak": 301.0}, "jerk": {"peak": 1, "p99": 1}})"),
       "joints.C.cuts.acceleration: p99 is missing"},
      {R"({"completed": true, "cycle_time_s": 1, "stops_in_cuts": 0, "joints": {}})",
       "joints.A.cuts is missing"},
      {"{", "bad.json"},
  };
  for (const auto& [text, message] : cases) {
    ASSERT_TRUE(WriteFileAtomically(file, text).ok());
    ControllerRun run;
    run.program = "untouched";
    const Status s = ReadControllerRun(file, &run);
    ASSERT_FALSE(s.ok()) << text;
    EXPECT_NE(s.message().find(message), std::string::npos) << s.message();
    EXPECT_NE(s.message().find(file), std::string::npos) << s.message();
    EXPECT_EQ(run.program, "untouched");
  }
}

}  // namespace
}  // namespace tpopt
