#pragma once
// Running the impactbench program as a user does, for the CLI tests: through the shell, with a
// time limit, in a folder of the test's own, its stdout and stderr captured.
#include <filesystem>
#include <string>

namespace impactbench::test_support {

/// A fresh folder below the system's temporary folder, removed with its contents at the end.
class TemporaryDirectory {
 public:
  explicit TemporaryDirectory(const std::string& prefix);
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

struct CliOutcome {
  int exit_code = -1;  ///< 124: the time limit was reached
  std::string out;
  std::string err;
};

/// The whole file as text (empty when it cannot be read).
std::string read_text(const std::filesystem::path& path);

/// Runs `[environment] timeout SECONDS PROGRAM ARGUMENTS` through the shell, in
/// `work_directory` when one is given; stdout and stderr go to files in `capture_directory`,
/// which are read and removed.
CliOutcome run_program(const std::filesystem::path& program, const std::string& arguments,
                       const std::filesystem::path& capture_directory,
                       const std::string& environment = "",
                       const std::filesystem::path& work_directory = {}, int seconds = 60);

}  // namespace impactbench::test_support
