#pragma once
// A file that appears only when complete: text is written to a temporary file in the target's
// directory (same filesystem, so the final rename is atomic) and renamed over the target by
// commit(). If commit() is never reached (an exception, a failed run), the destructor removes
// the temporary file, so no partial output is ever left behind.
#include <filesystem>
#include <fstream>

namespace impactbench::output {

class AtomicFile {
 public:
  /// Creates the temporary file; throws std::runtime_error if the directory is not writable.
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return stream_; }
  /// Flushes, checks every write succeeded and renames onto the target; throws
  /// std::runtime_error (and removes the temporary file) otherwise. Call at most once.
  void commit();

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporary() const { return temporary_; }

 private:
  void discard() noexcept;

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool done_ = false;
};

}  // namespace impactbench::output
