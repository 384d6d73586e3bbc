#pragma once
// A file that appears only when complete: text is written to a temporary file in the target's
// directory (same filesystem, so the final rename is atomic) and renamed over the target by
// commit(). If commit() is never reached (an exception, a failed run), the destructor removes
// the temporary file, so no partial output is ever left behind.
//
// The target is what the path names: a symbolic link is followed to the file it points to (the
// link stays), and an existing device node or FIFO (/dev/null, a pipe) is written through at
// commit instead of being replaced by a regular file. A new file gets the permissions the
// user's umask gives; an existing regular file keeps its mode.
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
  /// Flushes, checks every write succeeded and renames onto the target (or copies into a
  /// special file); throws std::runtime_error (and removes the temporary file) otherwise. Call
  /// at most once.
  void commit();

  /// The file written: the given path with symbolic links followed.
  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporary() const { return temporary_; }

 private:
  void discard() noexcept;
  void copy_into_special_target();

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool special_target_ = false;  ///< an existing device node or FIFO: written through
  bool done_ = false;
};

/// `path` with every symbolic link in its last component followed (also dangling ones, which
/// name the file to create); throws std::runtime_error for a loop.
std::filesystem::path follow_symlinks(const std::filesystem::path& path);

}  // namespace impactbench::output
