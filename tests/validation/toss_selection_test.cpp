// Toss numbers, the fixed train/test split and --tosses lists.
#include <gtest/gtest.h>

#include "lib/validation/toss_selection.hpp"

namespace impactbench::validation {
namespace {

TEST(TossSelection, NumbersSplitAndLists) {
  EXPECT_EQ(toss_number("d/toss_017.csv"), 17);
  EXPECT_EQ(toss_number("d/toss_000.csv"), 0);
  EXPECT_FALSE(toss_number("d/mine.csv").has_value());
  const auto train = parse_toss_selection("train");
  const auto test = parse_toss_selection("test");
  EXPECT_TRUE(train.contains("toss_016.csv"));
  EXPECT_FALSE(train.contains("toss_017.csv"));
  EXPECT_TRUE(test.contains("toss_017.csv"));
  EXPECT_FALSE(test.contains("mine.csv"));
  EXPECT_TRUE(parse_toss_selection("all").contains("mine.csv"));
  const auto list = parse_toss_selection("1,3,10-12");
  for (const int n : {1, 3, 10, 11, 12})
    EXPECT_TRUE(list.contains("toss_" + std::to_string(n) + ".csv"));
  for (const int n : {0, 2, 9, 13})
    EXPECT_FALSE(list.contains("toss_" + std::to_string(n) + ".csv"));
  for (const char* bad : {"", "odd", "1,", "3-1", "-2", "1,,2", "x-3"})
    EXPECT_THROW(parse_toss_selection(bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace impactbench::validation
