// Status codes and RETURN_IF_ERROR.
#include "model/base/status.h"

#include <gtest/gtest.h>

#include <string>

namespace tpopt {
namespace {

TEST(StatusTest, EachFactoryCarriesItsCodeAndMessage) {
  EXPECT_TRUE(Status::Ok().ok());
  EXPECT_EQ(Status::Ok().code(), StatusCode::kOk);
  EXPECT_TRUE(Status::Ok().message().empty());
  const struct {
    Status status;
    StatusCode code;
  } cases[] = {{Status::Error("a"), StatusCode::kBadInput},
               {Status::Usage("b"), StatusCode::kUsage},
               {Status::SolverFailure("c"), StatusCode::kSolver},
               {Status::IoError("d"), StatusCode::kIo}};
  std::string expected = "a";
  for (const auto& c : cases) {
    EXPECT_FALSE(c.status.ok()) << expected;
    EXPECT_EQ(c.status.code(), c.code) << expected;
    EXPECT_EQ(c.status.message(), expected);
    ++expected[0];
  }
}

// Counts its calls, and fails on the call numbered `fail_at`.
struct Step {
  int calls = 0;
  int fail_at = -1;
  Status operator()() {
    ++calls;
    return calls == fail_at ? Status::Usage("step " + std::to_string(calls))
                            : Status::Ok();
  }
};

Status ThreeSteps(Step* step, bool* reached_end) {
  RETURN_IF_ERROR((*step)());
  RETURN_IF_ERROR((*step)());
  RETURN_IF_ERROR((*step)());
  *reached_end = true;
  return Status::Ok();
}

TEST(StatusTest, ReturnIfErrorReturnsTheFirstFailureUnchangedAndEvaluatesOnce) {
  Step step;
  step.fail_at = 2;
  bool reached_end = false;
  const Status s = ThreeSteps(&step, &reached_end);
  EXPECT_EQ(step.calls, 2);  // stopped at the failure, each call made once
  EXPECT_FALSE(reached_end);
  EXPECT_EQ(s.code(), StatusCode::kUsage);
  EXPECT_EQ(s.message(), "step 2");
}

TEST(StatusTest, ReturnIfErrorPassesOkThrough) {
  Step step;
  bool reached_end = false;
  EXPECT_TRUE(ThreeSteps(&step, &reached_end).ok());
  EXPECT_EQ(step.calls, 3);
  EXPECT_TRUE(reached_end);
}

}  // namespace
}  // namespace tpopt
