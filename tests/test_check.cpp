// CANDELA_DCHECK: in a build that checks (debug, or CANDELA_FORCE_DCHECK as here) a failed
// invariant stops the program with the condition and its place; a holding one does nothing.
#define CANDELA_FORCE_DCHECK 1
#include <gtest/gtest.h>

#include "core/check.h"

namespace candela {
namespace {

TEST(DebugCheck, FailedInvariantAbortsNamingTheCondition) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");  // other tests leave oneTBB threads running
  const int count = 3;
  EXPECT_DEATH(CANDELA_DCHECK(count < 2), "CANDELA_DCHECK failed: count < 2");
}

TEST(DebugCheck, HoldingInvariantDoesNothing) {
  int evaluated = 0;
  CANDELA_DCHECK(++evaluated == 1);
  EXPECT_EQ(evaluated, 1);  // checked once, and execution went on
}

}  // namespace
}  // namespace candela
