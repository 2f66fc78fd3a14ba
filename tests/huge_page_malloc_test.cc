// The restart for huge-page malloc: when it happens, and that the tpopt
// command really runs with the tunable in effect (its report says so).
#include "apps/huge_page_malloc.h"

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::ReadFileText;
using testing::ReadJson;
using testing::RunCommand;
using testing::SourcePath;
using testing::TempDir;
using testing::Tpopt;

constexpr char kMadvise[] = "always [madvise] never\n";

TEST(HugePageMallocTest, RestartsOnlyWhenTheTunableWouldHelpAndIsUnset) {
  EXPECT_TRUE(ShouldRestartForHugePages(nullptr, nullptr, nullptr, kMadvise));
  EXPECT_TRUE(ShouldRestartForHugePages("glibc.malloc.arena_max=2", "1", nullptr, kMadvise));
  // Already restarted, switched off, or the user's own setting.
  EXPECT_FALSE(ShouldRestartForHugePages(nullptr, nullptr, "1", kMadvise));
  EXPECT_FALSE(ShouldRestartForHugePages(nullptr, "0", nullptr, kMadvise));
  EXPECT_FALSE(ShouldRestartForHugePages("glibc.malloc.hugetlb=0", nullptr, nullptr, kMadvise));
  // Kernel modes where madvise changes nothing, or no THP at all.
  EXPECT_FALSE(ShouldRestartForHugePages(nullptr, nullptr, nullptr, "[always] madvise never\n"));
  EXPECT_FALSE(ShouldRestartForHugePages(nullptr, nullptr, nullptr, "always madvise [never]\n"));
  EXPECT_FALSE(ShouldRestartForHugePages(nullptr, nullptr, nullptr, ""));
}

// What `tpopt evaluate` records in its report under the given environment
// prefix (`env ...`).
bool ReportedHugePageMalloc(const std::string& env) {
  TempDir dir;
  const std::string surface = SourcePath("data/surfaces/hypar.json");
  const std::string cls = dir.File("p.cls"), report = dir.File("r.json");
  auto r = RunCommand(Tpopt("generate --surface=" + surface +
                            " --cutter_radius=4 --poses=20 --strategy=spo --out=" + cls));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = RunCommand(env + " " + Tpopt("evaluate --quiet --in=" + cls + " --surface=" + surface +
                                   " --report=" + report));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json json = ReadJson(report);
  EXPECT_TRUE(json.contains("huge_page_malloc")) << json.dump();
  return json.value("huge_page_malloc", false);
}

TEST(HugePageMallocTest, TheCommandRunsWithTheTunableWhereTheKernelAdvisesIt) {
  const std::string mode = ReadFileText("/sys/kernel/mm/transparent_hugepage/enabled");
  const bool expected =
      mode.find("[madvise]") != std::string::npos && !RunsUnderAddressSanitizer();
  const std::string clean = "env -u GLIBC_TUNABLES -u TPOPT_HUGE_PAGES -u TPOPT_HUGE_PAGES_RESTARTED";
  EXPECT_EQ(ReportedHugePageMalloc(clean), expected) << "THP mode: " << mode;
  EXPECT_FALSE(ReportedHugePageMalloc(clean + " TPOPT_HUGE_PAGES=0"));
  EXPECT_FALSE(ReportedHugePageMalloc(clean + " GLIBC_TUNABLES=glibc.malloc.hugetlb=0"));
}

}  // namespace
}  // namespace tpopt
