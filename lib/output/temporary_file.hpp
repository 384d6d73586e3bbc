#pragma once
// The storage behind an AtomicFile until it is published. Preferably an unnamed file (Linux
// O_TMPFILE) in the target's directory: it has no name until it is linked at the target, so a
// run killed by any signal, SIGKILL included, leaves nothing behind. Where the filesystem has no
// unnamed files, a hidden named file ".<name>.XXXXXX" beside the target, which a SIGINT or SIGTERM
// removes before the process ends (an uncatchable SIGKILL can then leave it).
#include <sys/types.h>
#include <filesystem>
#include <string>

namespace impactbench::output {

class TemporaryFile {
 public:
  /// Creates it in `directory` with permissions `mode`; throws std::runtime_error naming
  /// `target` (the file it stands for) when it cannot.
  TemporaryFile(const std::filesystem::path& directory, const std::filesystem::path& target,
                mode_t mode);
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile();

  /// A path that opens this file for writing and reading (/proc/self/fd/N for an unnamed one).
  const std::filesystem::path& access_path() const { return access_path_; }
  /// Gives the file the name `target`, replacing what was there atomically; false with errno
  /// set when that fails (the temporary then still exists).
  bool publish_as(const std::filesystem::path& target);
  /// Removes it (no effect once published). Never throws.
  void remove() noexcept;

 private:
  int descriptor_ = -1;               // the unnamed file's, kept open until published
  std::filesystem::path named_path_;  // the named fallback's path, empty for an unnamed file
  std::filesystem::path access_path_;
};

}  // namespace impactbench::output
