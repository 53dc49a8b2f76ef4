// The pace every renderer renders a frame at (film/pass_schedule.h): passes of 1, 1, 2, 4, …
// samples up to the largest, every sample exactly once and in order; cancellation and the team's
// verdict stop it after the pass they come in, counted or not as the renderer treats a pass under
// way; progress in 64 bits for the longest renders.
#include "obscura/film/pass_schedule.h"

#include <gtest/gtest.h>

#include <atomic>
#include <limits>
#include <vector>

#include "obscura/math/error.h"

namespace obscura {
namespace {

std::vector<int> pass_sizes(int samples, int largest) {
  PassSchedule passes(samples, largest, OnCancel::kAbandonPass, {});
  std::vector<int> sizes;
  int next_first = 0;
  Pass pass;
  while (passes.next(pass)) {
    EXPECT_EQ(pass.first, next_first);  // in order, none skipped, none twice
    next_first = pass.end;
    sizes.push_back(pass.size());
    passes.finish(pass);
  }
  EXPECT_EQ(next_first, samples);
  EXPECT_EQ(passes.done(), samples);
  EXPECT_FALSE(passes.cancelled() || passes.time_limited());
  return sizes;
}

TEST(PassSchedule, PassesDoubleFromOneUpToTheLargest) {
  EXPECT_EQ(pass_sizes(1, 64), (std::vector<int>{1}));
  EXPECT_EQ(pass_sizes(16, 64), (std::vector<int>{1, 1, 2, 4, 8}));
  EXPECT_EQ(pass_sizes(20, 64), (std::vector<int>{1, 1, 2, 4, 8, 4}));
  EXPECT_EQ(pass_sizes(300, 64), (std::vector<int>{1, 1, 2, 4, 8, 16, 32, 64, 64, 64, 44}));
  EXPECT_EQ(pass_sizes(4, 1), (std::vector<int>{1, 1, 1, 1}));  // a frame per pass
}

TEST(PassSchedule, CancellationStopsAfterThePassItCameIn) {
  for (OnCancel on_cancel : {OnCancel::kAbandonPass, OnCancel::kCompletePass}) {
    std::atomic<bool> cancel{false};
    PassSchedule passes(64, 64, on_cancel, {.cancel = &cancel});
    Pass pass;
    ASSERT_TRUE(passes.next(pass));
    passes.finish(pass);
    ASSERT_TRUE(passes.next(pass));
    EXPECT_FALSE(passes.cancel_requested());
    cancel = true;  // during the second pass
    EXPECT_TRUE(passes.cancel_requested());
    passes.finish(pass);
    EXPECT_FALSE(passes.next(pass));
    EXPECT_TRUE(passes.cancelled());
    EXPECT_FALSE(passes.time_limited());
    // A renderer that abandons a pass under way has one whole pass; one that completes it, two.
    EXPECT_EQ(passes.done(), on_cancel == OnCancel::kAbandonPass ? 1 : 2);
  }
}

TEST(PassSchedule, EveryPartFollowsTheTeamsVerdict) {
  int settles = 0;
  WorkShare share{.part = 1, .parts = 3, .settle = [&](StopVerdict own) {
                    EXPECT_EQ(own, StopVerdict::kGoOn);  // nothing stops this part itself
                    return ++settles == 3 ? StopVerdict::kTimeLimit : StopVerdict::kGoOn;
                  }};
  PassSchedule passes(64, 64, OnCancel::kAbandonPass, {.share = &share});
  Pass pass;
  int rendered = 0;
  while (passes.next(pass)) {
    ++rendered;
    passes.finish(pass);
  }
  EXPECT_EQ(settles, 3);
  EXPECT_EQ(rendered, 3);
  EXPECT_TRUE(passes.time_limited());
  EXPECT_EQ(passes.done(), 4);  // 1 + 1 + 2: a time limit keeps the pass it stopped after
}

TEST(PassSchedule, ATimeLimitStopsBeforeAPassThatWouldOverrunIt) {
  // No pass can be predicted to end within a nanosecond: the first pass (always rendered) is the
  // last.
  PassSchedule passes(1000, 64, OnCancel::kAbandonPass, {.time_limit_s = 1e-9});
  Pass pass;
  ASSERT_TRUE(passes.next(pass));
  passes.finish(pass);
  EXPECT_FALSE(passes.next(pass));
  EXPECT_TRUE(passes.time_limited());
  EXPECT_EQ(passes.done(), 1);
  // Once every sample is in, the time limit has nothing left to stop.
  PassSchedule one(1, 64, OnCancel::kAbandonPass, {.time_limit_s = 1e-9});
  ASSERT_TRUE(one.next(pass));
  one.finish(pass);
  EXPECT_FALSE(one.time_limited());
}

TEST(PassSchedule, ProgressFitsAnIntForTheLongestRenders) {
  const int samples = 1 << 30;  // what a time-limited render without a sample count asks for
  PassSchedule passes(samples, 64, OnCancel::kAbandonPass, {});
  int done = -1, total = -1;
  passes.report([&](int d, int t) { done = d, total = t; }, {.first = samples / 2, .end = samples},
                1000, 4000);
  ASSERT_GT(total, 0);
  EXPECT_NEAR(double(done) / total, 0.625, 1e-6);   // half, then a quarter of the second half
  passes.report({}, {.first = 0, .end = 1}, 0, 1);  // no callback: nothing to call
}

TEST(PassSchedule, RefusesNoSamplesAndNegativeTimeLimits) {
  EXPECT_THROW(PassSchedule(0, 64, OnCancel::kAbandonPass, {}), Error);
  EXPECT_THROW(PassSchedule(4, 64, OnCancel::kAbandonPass, {.time_limit_s = -1}), Error);
  EXPECT_THROW(PassSchedule(4, 64, OnCancel::kAbandonPass,
                            {.time_limit_s = std::numeric_limits<double>::quiet_NaN()}),
               Error);
}

}  // namespace
}  // namespace obscura
