#include "lib/output/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>     // open
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

bool is_special_file(const std::filesystem::path& path) {
  struct stat status {};  // stat follows every link, /proc's magic ones too
  return ::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode) && !S_ISDIR(status.st_mode);
}

std::filesystem::path output_target(const std::filesystem::path& path) {
  return is_special_file(path) ? path : follow_symlinks(path);
}

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(output_target(target)), special_target_(is_special_file(target_)) {
  struct stat existing {};
  const bool exists = ::stat(target_.c_str(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode)) fail(target_, "it is a directory");
  // A special file's directory (/dev) is usually not writable: its copy waits elsewhere.
  std::error_code no_temp;
  const auto directory = special_target_             ? std::filesystem::temp_directory_path(no_temp)
                         : target_.has_parent_path() ? target_.parent_path()
                                                     : std::filesystem::path(".");
  const mode_t mode =
      exists && !special_target_ ? static_cast<mode_t>(existing.st_mode & 07777) : new_file_mode();
  temporary_.emplace(directory, target_, mode);
  stream_.open(temporary_->access_path(), std::ios::out | std::ios::trunc);
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
  if (temporary_) temporary_->remove();
}

void AtomicFile::copy_into_special_target() {
  std::ifstream in(temporary_->access_path(), std::ios::binary);
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

void AtomicFile::finish_writing() {
  if (done_) throw std::logic_error("AtomicFile::commit called twice for " + target_.string());
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail()) {
    discard();
    fail(target_, "write failed");
  }
}

void AtomicFile::publish() {
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
  if (!temporary_->publish_as(target_)) {
    const int saved_errno = errno;
    discard();
    fail(target_, std::strerror(saved_errno));
  }
  done_ = true;
}

void AtomicFile::commit() {
  commit_together({this});
}

void commit_together(std::initializer_list<AtomicFile*> files) {
  const auto discard_all = [&] {
    for (AtomicFile* file : files) file->discard();
  };
  try {
    for (AtomicFile* file : files) file->finish_writing();
    for (AtomicFile* file : files)
      if (file->special_target_) file->publish();
  } catch (...) {
    discard_all();
    throw;
  }
  std::vector<const AtomicFile*> published;
  try {
    for (AtomicFile* file : files) {
      if (file->special_target_) continue;
      file->publish();
      published.push_back(file);
    }
  } catch (...) {
    for (const AtomicFile* file : published) {
      std::error_code ignored;
      std::filesystem::remove(file->target_, ignored);
    }
    discard_all();
    throw;
  }
}

}  // namespace impactbench::output
