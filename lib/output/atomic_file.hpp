#pragma once
// A file that appears only when complete: text is written to a temporary file in the target's
// directory (temporary_file.hpp: unnamed where the filesystem allows, so even a killed run leaves
// nothing) and published at the target by commit(). If commit() is never reached (an exception,
// a failed run), the destructor removes the temporary, so no partial output is ever left behind.
//
// The target is what the path names: a symbolic link is followed to the file it points to (the
// link stays), and an existing device node, FIFO or socket (/dev/null, a pipe behind
// /dev/stdout) is written through at commit instead of being replaced by a regular file. A new
// file gets the permissions the user's umask gives; an existing regular file keeps its mode.
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <optional>

#include "lib/output/temporary_file.hpp"

namespace impactbench::output {

class AtomicFile {
 public:
  /// Creates the temporary file; throws std::runtime_error if the directory is not writable.
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  std::ostream& stream() { return stream_; }
  /// Flushes, checks every write succeeded and publishes at the target (or copies into a
  /// special file); throws std::runtime_error (and removes the temporary file) otherwise. Call
  /// at most once.
  void commit();

  /// The file written: the given path with symbolic links followed (a special file's own path).
  const std::filesystem::path& target() const { return target_; }

  /// Commits several files as one: every file is completed first, then the special targets are
  /// written through, then the others published. When any step fails, none of the regular
  /// targets is left (those already published in this call are removed) and it throws.
  friend void commit_together(std::initializer_list<AtomicFile*> files);

 private:
  void finish_writing();  // flush, close and check the temporary; throws
  void publish();         // into the target; throws
  void discard() noexcept;
  void copy_into_special_target();

  std::filesystem::path target_;
  std::optional<TemporaryFile> temporary_;
  std::ofstream stream_;
  bool special_target_ = false;  ///< an existing device node, FIFO or socket: written through
  bool done_ = false;
};

void commit_together(std::initializer_list<AtomicFile*> files);

/// Whether `path`, every link followed (the kernel's magic /proc links too), is an existing
/// device node, FIFO or socket: a file written through rather than replaced.
bool is_special_file(const std::filesystem::path& path);

/// The file an output path writes: a special file's own path (its link text, "pipe:[N]" behind
/// /dev/stdout, names no file), otherwise the path with its symbolic links followed.
std::filesystem::path output_target(const std::filesystem::path& path);

/// `path` with every symbolic link in its last component followed (also dangling ones, which
/// name the file to create); throws std::runtime_error for a loop.
std::filesystem::path follow_symlinks(const std::filesystem::path& path);

}  // namespace impactbench::output
