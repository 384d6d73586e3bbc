// docs/settings.md is what `impactbench settings-page` makes from the engines' settings
// schemas, byte for byte: a setting, its default, its range or its meaning changed in the code
// and not in the page (or in the page and not in the code) fails here.
#include <cstddef>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::test_support::CliOutcome;
using impactbench::test_support::read_text;
using impactbench::test_support::run_program;
using impactbench::test_support::TemporaryDirectory;

const fs::path kPage = fs::path(IMPACTBENCH_TEST_DATA_DIR) / ".." / ".." / "docs" / "settings.md";

/// "line N: page 'X' / code 'Y'" for the first line where the two texts differ.
std::string first_difference(const std::string& page, const std::string& generated) {
  std::size_t line = 1;
  std::size_t start = 0;
  while (true) {
    const std::size_t page_end = page.find('\n', start);
    const std::size_t code_end = generated.find('\n', start);
    const std::string page_line = page.substr(start, page_end - start);
    const std::string code_line = generated.substr(start, code_end - start);
    if (page_line != code_line || page_end != code_end)
      return "line " + std::to_string(line) + ":\n  page: " + page_line + "\n  code: " + code_line;
    if (page_end == std::string::npos) return "none";
    start = page_end + 1;
    ++line;
  }
}

TEST(SettingsPage, IsWhatTheSchemasGenerate) {
  const TemporaryDirectory capture("impactbench_settings_page");
  const CliOutcome outcome = run_program(IMPACTBENCH_CLI, "settings-page", capture.path());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  const std::string page = read_text(kPage);
  ASSERT_FALSE(page.empty()) << "cannot read " << kPage;
  EXPECT_TRUE(page == outcome.out)
      << "docs/settings.md differs from the settings in the code, first at "
      << first_difference(page, outcome.out)
      << "\nRegenerate it from the checkout's root with\n"
         "  build/tests/bin/impactbench settings-page > docs/settings.md";
}

TEST(SettingsPage, IsHiddenFromHelpAndFromTheCommandList) {
  const TemporaryDirectory capture("impactbench_settings_page");
  const CliOutcome help = run_program(IMPACTBENCH_CLI, "--help", capture.path());
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("describe"), std::string::npos) << help.out;
  EXPECT_EQ(help.out.find("settings-page"), std::string::npos) << help.out;
  const CliOutcome typo = run_program(IMPACTBENCH_CLI, "lst", capture.path());
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_NE(typo.err.find("commands: list,"), std::string::npos) << typo.err;
  EXPECT_EQ(typo.err.find("settings-page"), std::string::npos) << typo.err;
}

}  // namespace
