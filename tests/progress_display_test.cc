#include "apps/progress_display.h"

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include <gtest/gtest.h>

namespace tpopt {
namespace {

// Runs `body` against a display writing to a temporary (non-terminal) file
// and returns what the display wrote, once it is destroyed.
template <typename Body>
std::string Capture(bool enabled, double delay_s, Body body) {
  FILE* file = std::tmpfile();
  {
    ProgressDisplay display(file, "tpopt test", enabled, delay_s);
    body(&display);
  }
  std::rewind(file);
  std::string text;
  char buffer[512];
  for (size_t n; (n = std::fread(buffer, 1, sizeof(buffer), file)) > 0;) text.append(buffer, n);
  std::fclose(file);
  return text;
}

void Wait(double seconds) {
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
}

TEST(ProgressDisplayTest, ShowsStagesAndDetailsOncePastTheDelay) {
  const std::string text = Capture(true, 0.0, [](ProgressDisplay* p) {
    p->SetStage("evaluating the input");
    Wait(0.3);
    p->SetStage("high_accuracy solve");
    p->SetDetail("iteration 3, cost 1.0e-02");
    Wait(0.7);
  });
  const size_t first = text.find("tpopt test [");
  ASSERT_NE(first, std::string::npos) << text;
  EXPECT_NE(text.find("] evaluating the input\n"), std::string::npos) << text;
  const size_t solve = text.find("] high_accuracy solve: iteration 3, cost 1.0e-02\n");
  ASSERT_NE(solve, std::string::npos) << text;
  EXPECT_LT(text.find("evaluating the input"), solve);
}

TEST(ProgressDisplayTest, EveryStagePastTheDelayIsLoggedHoweverShort) {
  const std::string text = Capture(true, 0.0, [](ProgressDisplay* p) {
    p->SetStage("first");
    p->SetStage("second");
    p->SetDetail("last word");
  });
  EXPECT_NE(text.find("] first\n"), std::string::npos) << text;
  EXPECT_NE(text.find("] second\n"), std::string::npos) << text;
  EXPECT_NE(text.find("] second: last word\n"), std::string::npos) << text;
}

TEST(ProgressDisplayTest, ALogGetsALineOnlyWhenTheTextChanges) {
  const std::string text = Capture(true, 0.0, [](ProgressDisplay* p) {
    p->SetStage("waiting");
    Wait(0.8);  // several ticks, one piece of news
  });
  size_t lines = 0;
  for (char c : text) lines += c == '\n';
  EXPECT_EQ(lines, 1u) << text;
}

TEST(ProgressDisplayTest, ShortRunsAndQuietRunsShowNothing) {
  EXPECT_EQ(Capture(true, 10.0,
                    [](ProgressDisplay* p) {
                      p->SetStage("quick");
                      Wait(0.3);
                    }),
            "");
  EXPECT_EQ(Capture(false, 0.0,
                    [](ProgressDisplay* p) {
                      p->SetStage("quiet");
                      Wait(0.3);
                    }),
            "");
}

}  // namespace
}  // namespace tpopt
