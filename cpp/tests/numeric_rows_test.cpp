#include "nonobtuse/numeric_rows.h"

#include <gtest/gtest.h>

#include <cmath>

namespace nonobtuse {
namespace {

TEST(NumericRows, PlainRowsAreParsedCorrectlyRounded) {
  auto v = parse_numeric_rows("1 0.1 -2e3\n2\t+.5   5.\n", 2, 3, {0});
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, (std::vector<double>{1, 0.1, -2000, 2, 0.5, 5}));
  // The nearest double to 0.1 and the subnormal minimum, as strtod gives them.
  v = parse_numeric_rows("0.1 5e-324 -0", 1, 3, {});
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ((*v)[0], std::strtod("0.1", nullptr));
  EXPECT_EQ((*v)[1], std::strtod("5e-324", nullptr));
  EXPECT_TRUE(std::signbit((*v)[2]));
}

TEST(NumericRows, AnythingElseIsRefused) {
  for (const char* text : {"1 2 3\n4 5", "1 2 3\n4 5 6 7", "1 2 3\n\n4 5 6", "1 2 3 # c\n4 5 6", "1 nan 3\n4 5 6",
                           "1 inf 3\n4 5 6", "1 0x1 3\n4 5 6", "1 1_0 3\n4 5 6", "1 0.5-1 3\n4 5 6",
                           "1 ++1 3\n4 5 6", "1 +-1 3\n4 5 6", "1 . 3\n4 5 6", "1 1e 3\n4 5 6", "1 1e400 3\n4 5 6",
                           "1.0 2 3\n4 5 6", "1e1 2 3\n4 5 6", "9007199254740993 2 3\n4 5 6",
                           "9007199254740992 2 3\n4 5 6", "1 2 3\r\n4 5 6",
                           "1 2 3\n4 5 6\n7 8 9"})
    EXPECT_FALSE(parse_numeric_rows(text, 2, 3, {0}).has_value()) << text;
  // 2^53 - 1 is read exactly; 2^53 + 1 would round to 2^53, so 2^53 and above go to the line reader.
  auto v = parse_numeric_rows("9007199254740991 2 3\n4 5 6", 2, 3, {0});
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ((*v)[0], 9007199254740991.0);
}

}  // namespace
}  // namespace nonobtuse
