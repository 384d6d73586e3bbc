#pragma once
// Which toss files a validation scores. A toss's number is the digits ending its file name
// (toss_017.csv: 17). The fixed split of the shipped tosses: even numbers train (fits), odd
// numbers test (scores); docs/real-tosses.md states it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impactbench::validation {

/// The number ending the file's stem; empty when the stem does not end in a digit.
std::optional<int> toss_number(const std::filesystem::path& file);

/// "all", "train" (even numbers), "test" (odd numbers), or a comma-separated list of numbers
/// and inclusive ranges ("1,3,10-20"). Throws std::invalid_argument on anything else.
struct TossSelection {
  enum class Kind { kAll, kTrain, kTest, kList } kind = Kind::kTest;
  std::vector<std::pair<int, int>> ranges;  ///< kList: inclusive [first, last]
  bool contains(const std::filesystem::path& file) const;
};
TossSelection parse_toss_selection(const std::string& text);

/// The *.csv files of `directory`, sorted by name, that `selection` contains. Throws
/// std::runtime_error when the directory cannot be listed.
std::vector<std::filesystem::path> select_toss_files(const std::filesystem::path& directory,
                                                     const TossSelection& selection);

}  // namespace impactbench::validation
