#include "lib/output/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>     // open
#include <stdlib.h>    // mkstemp (POSIX)
#include <sys/stat.h>  // stat, fchmod, umask
#include <unistd.h>    // close, write

namespace impactbench::output {

namespace {

constexpr int kMaxSymlinkHops = 40;  // as the kernel's ELOOP limit

[[noreturn]] void fail(const std::filesystem::path& target, const std::string& why) {
  throw std::runtime_error("cannot write " + target.string() + ": " + why);
}

/// The mode a file created with 0666 gets under the process umask (read once: umask() can
/// only be read by setting it).
mode_t new_file_mode() {
  static const mode_t mode = [] {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return static_cast<mode_t>(0666 & ~mask);
  }();
  return mode;
}

}  // namespace

std::filesystem::path follow_symlinks(const std::filesystem::path& path) {
  std::filesystem::path current = path;
  for (int hop = 0; hop < kMaxSymlinkHops; ++hop) {
    std::error_code error;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(current, error)))
      return current;
    const auto link = std::filesystem::read_symlink(current, error);
    if (error) fail(path, error.message());
    current = link.is_absolute() ? link : current.parent_path() / link;
  }
  fail(path, "too many levels of symbolic links");
}

AtomicFile::AtomicFile(std::filesystem::path target) : target_(follow_symlinks(target)) {
  struct stat existing {};
  const bool exists = ::stat(target_.c_str(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode)) fail(target_, "it is a directory");
  special_target_ = exists && !S_ISREG(existing.st_mode);
  // A special file's directory (/dev) is usually not writable: its copy waits elsewhere.
  std::error_code no_temp;
  const auto directory = special_target_             ? std::filesystem::temp_directory_path(no_temp)
                         : target_.has_parent_path() ? target_.parent_path()
                                                     : std::filesystem::path(".");
  // Hidden, unique name next to the target: ".<name>.XXXXXX".
  std::string hidden_name(".");
  hidden_name.append(target_.filename().string()).append(".XXXXXX");
  const std::string pattern = (directory / hidden_name).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int descriptor = ::mkstemp(name.data());
  if (descriptor < 0) fail(target_, std::strerror(errno));
  // mkstemp creates 0600; give the file the mode it will keep after the rename.
  const mode_t mode =
      exists && !special_target_ ? static_cast<mode_t>(existing.st_mode & 07777) : new_file_mode();
  const int chmod_result = ::fchmod(descriptor, mode);
  ::close(descriptor);
  temporary_ = name.data();
  if (chmod_result != 0) {
    discard();
    fail(target_, std::strerror(errno));
  }
  stream_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!stream_) {
    discard();
    fail(target_, "cannot open a temporary file");
  }
}

AtomicFile::~AtomicFile() {
  if (!done_) discard();
}

void AtomicFile::discard() noexcept {
  done_ = true;
  if (stream_.is_open()) stream_.close();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::copy_into_special_target() {
  std::ifstream in(temporary_, std::ios::binary);
  const int descriptor = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC);
  if (descriptor < 0) fail(target_, std::strerror(errno));
  char buffer[1 << 16];
  bool ok = true;
  int saved_errno = 0;
  while (ok && in) {
    in.read(buffer, sizeof buffer);
    const char* data = buffer;
    for (std::streamsize left = in.gcount(); left > 0;) {
      const ssize_t written = ::write(descriptor, data, static_cast<std::size_t>(left));
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) {
        ok = false;
        saved_errno = errno;
        break;
      }
      data += written;
      left -= written;
    }
  }
  ::close(descriptor);
  if (!ok) fail(target_, saved_errno ? std::strerror(saved_errno) : "write failed");
}

void AtomicFile::commit() {
  if (done_) throw std::logic_error("AtomicFile::commit called twice for " + target_.string());
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail()) {
    discard();
    fail(target_, "write failed");
  }
  if (special_target_) {
    try {
      copy_into_special_target();
    } catch (...) {
      discard();
      throw;
    }
    discard();
    return;
  }
  std::error_code error;
  std::filesystem::rename(temporary_, target_, error);
  if (error) {
    discard();
    fail(target_, error.message());
  }
  done_ = true;
}

}  // namespace impactbench::output
