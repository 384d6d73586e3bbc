#include "lib/validation/toss_selection.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>
#include <stdexcept>

#include "lib/output/message_text.hpp"

namespace impactbench::validation {
namespace {

int parse_number(const std::string& text, const std::string& whole) {
  int value = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < 0)
    throw std::invalid_argument("--tosses: '" + output::printable(whole, 80) +
                                "' is not all, train, test or a list like 1,3,10-20");
  return value;
}

}  // namespace

std::optional<int> toss_number(const std::filesystem::path& file) {
  const std::string stem = file.stem().string();
  std::size_t start = stem.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(stem[start - 1]))) --start;
  if (start == stem.size() || stem.size() - start > 9) return std::nullopt;
  return std::stoi(stem.substr(start));
}

bool TossSelection::contains(const std::filesystem::path& file) const {
  if (kind == Kind::kAll) return true;
  const auto number = toss_number(file);
  if (!number) return false;
  switch (kind) {
    case Kind::kTrain:
      return *number % 2 == 0;
    case Kind::kTest:
      return *number % 2 == 1;
    default:
      return std::any_of(ranges.begin(), ranges.end(),
                         [&](const auto& r) { return r.first <= *number && *number <= r.second; });
  }
}

TossSelection parse_toss_selection(const std::string& text) {
  TossSelection selection;
  if (text == "all") selection.kind = TossSelection::Kind::kAll;
  if (text == "train") selection.kind = TossSelection::Kind::kTrain;
  if (text == "test") selection.kind = TossSelection::Kind::kTest;
  if (text == "all" || text == "train" || text == "test") return selection;
  selection.kind = TossSelection::Kind::kList;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto dash = item.find('-');
    const int first = parse_number(item.substr(0, dash), text);
    const int last = dash == std::string::npos ? first : parse_number(item.substr(dash + 1), text);
    if (last < first)
      throw std::invalid_argument("--tosses: range '" + output::printable(item, 40) +
                                  "' ends before it starts");
    selection.ranges.emplace_back(first, last);
  }
  if (selection.ranges.empty() || text.back() == ',') parse_number("", text);
  return selection;
}

std::vector<std::filesystem::path> select_toss_files(const std::filesystem::path& directory,
                                                     const TossSelection& selection) {
  std::error_code error;
  std::vector<std::filesystem::path> files;
  for (std::filesystem::directory_iterator it(directory, error), end; !error && it != end;
       it.increment(error))
    if (it->path().extension() == ".csv" && selection.contains(it->path()))
      files.push_back(it->path());
  if (error)
    throw std::runtime_error("cannot list the toss directory " +
                             output::printable(directory.string()) + ": " + error.message());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace impactbench::validation
