// The names of the public enums, as the Python layer and the CLI print them.
#include "nonobtuse/types.h"

#include <gtest/gtest.h>

namespace nonobtuse {
namespace {

TEST(Types, RefineStatusNames) {
  EXPECT_STREQ(to_string(RefineStatus::Converged), "converged");
  EXPECT_STREQ(to_string(RefineStatus::BudgetExhausted), "budget_exhausted");
  EXPECT_STREQ(to_string(RefineStatus::MinLengthReached), "min_length_reached");
  EXPECT_STREQ(to_string(RefineStatus::Stalled), "stalled");
}

}  // namespace
}  // namespace nonobtuse
