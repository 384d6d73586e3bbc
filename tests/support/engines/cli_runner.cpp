#include "tests/support/engines/cli_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impactbench::test_support {

namespace fs = std::filesystem;

TemporaryDirectory::TemporaryDirectory(const std::string& prefix) {
  std::string pattern = (fs::temp_directory_path() / (prefix + "_XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::runtime_error("cannot create a temporary folder " + pattern);
  path_ = pattern;
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

CliOutcome run_program(const fs::path& program, const std::string& arguments,
                       const fs::path& capture_directory, const std::string& environment,
                       const fs::path& work_directory, int seconds) {
  const fs::path out = capture_directory / "stdout", err = capture_directory / "stderr";
  std::string command;
  if (!work_directory.empty()) command = "cd '" + work_directory.string() + "' || exit 99; ";
  command += environment + " timeout " + std::to_string(seconds) + " '" + program.string() + "' " +
             arguments + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  CliOutcome outcome;
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  outcome.out = read_text(out);
  outcome.err = read_text(err);
  fs::remove(out);
  fs::remove(err);
  return outcome;
}

}  // namespace impactbench::test_support
