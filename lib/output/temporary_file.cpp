#include "lib/output/temporary_file.hpp"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include <fcntl.h>     // open, O_TMPFILE, linkat
#include <stdlib.h>    // mkstemp (POSIX)
#include <sys/stat.h>  // fchmod
#include <unistd.h>    // close, unlink

namespace impactbench::output {

namespace {

[[noreturn]] void fail(const std::filesystem::path& target, const std::string& why) {
  throw std::runtime_error("cannot write " + target.string() + ": " + why);
}

// Named temporaries that a SIGINT or SIGTERM must remove. The handler may only touch what is
// async-signal-safe: fixed slots of path text, claimed and released with atomic flags.
constexpr std::size_t kSlots = 16;
constexpr std::size_t kSlotLength = 4096;
struct Slot {
  std::atomic<bool> used{false};
  char path[kSlotLength]{};
};
std::array<Slot, kSlots> pending_removals;

extern "C" void remove_temporaries_and_reraise(int signal_number) {
  for (Slot& slot : pending_removals)
    if (slot.used.load()) ::unlink(slot.path);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void install_interrupt_cleanup() {
  static const bool installed = [] {
    for (const int signal_number : {SIGINT, SIGTERM}) {
      struct sigaction previous {};
      ::sigaction(signal_number, nullptr, &previous);
      if (previous.sa_handler != SIG_DFL) continue;  // the program handles it itself
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_reraise;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal_number, &action, nullptr);
    }
    return true;
  }();
  (void)installed;
}

/// Claims a slot for `path` (false when none is free or the path is too long: then a signal
/// can leave that temporary, as before there was any cleanup).
bool remember_for_interrupts(const std::string& path) {
  if (path.size() >= kSlotLength) return false;
  install_interrupt_cleanup();
  for (Slot& slot : pending_removals) {
    bool expected = false;
    if (!slot.used.load() && slot.path[0] == '\0' &&
        slot.used.compare_exchange_strong(expected, true)) {
      std::memcpy(slot.path, path.c_str(), path.size() + 1);
      return true;
    }
  }
  return false;
}

void forget_for_interrupts(const std::string& path) {
  for (Slot& slot : pending_removals) {
    if (slot.used.load() && path == slot.path) {
      slot.used.store(false);
      slot.path[0] = '\0';
      return;
    }
  }
}

/// A hidden name beside `target` that does not exist yet: ".<name>.<random>".
std::filesystem::path unused_hidden_name(const std::filesystem::path& target) {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  for (;;) {
    // Appends only: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string at -O3.
    std::string name(".");
    name.append(target.filename().string())
        .append(".")
        .append(std::to_string(random() % 1000000000));
    const auto candidate = target.parent_path() / name;
    std::error_code error;
    if (!std::filesystem::exists(std::filesystem::symlink_status(candidate, error)))
      return candidate;
  }
}

}  // namespace

TemporaryFile::TemporaryFile(const std::filesystem::path& directory,
                             const std::filesystem::path& target, mode_t mode) {
#ifdef O_TMPFILE
  descriptor_ = ::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, mode);
  if (descriptor_ >= 0) {
    access_path_ = "/proc/self/fd/" + std::to_string(descriptor_);
    // Reopening through /proc needs /proc; without it the named fallback serves.
    if (::access(access_path_.c_str(), W_OK) == 0 && ::fchmod(descriptor_, mode) == 0) return;
    ::close(descriptor_);
    descriptor_ = -1;
  } else if (errno == ENOENT || errno == ENOTDIR || errno == EACCES || errno == EROFS) {
    fail(target, std::strerror(errno));  // the directory, not the feature, is the problem
  }
#endif
  std::string hidden(".");
  hidden.append(target.filename().string()).append(".XXXXXX");
  const std::string pattern = (directory / hidden).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int descriptor = ::mkstemp(name.data());
  if (descriptor < 0) fail(target, std::strerror(errno));
  named_path_ = name.data();
  remember_for_interrupts(named_path_.string());
  // mkstemp creates 0600; give the file the mode it will keep after the rename.
  const int chmod_result = ::fchmod(descriptor, mode);
  const int saved_errno = errno;
  ::close(descriptor);
  access_path_ = named_path_;
  if (chmod_result != 0) {
    remove();
    fail(target, std::strerror(saved_errno));
  }
}

TemporaryFile::~TemporaryFile() {
  remove();
}

bool TemporaryFile::publish_as(const std::filesystem::path& target) {
  if (named_path_.empty()) {
    // Linked straight at the target when it does not exist; else under a fresh hidden name,
    // then renamed over it (the name exists only between the two calls).
    const bool linked =
        ::linkat(AT_FDCWD, access_path_.c_str(), AT_FDCWD, target.c_str(), AT_SYMLINK_FOLLOW) == 0;
    if (!linked) {
      if (errno != EEXIST) return false;
      const auto hidden = unused_hidden_name(target);
      if (::linkat(AT_FDCWD, access_path_.c_str(), AT_FDCWD, hidden.c_str(), AT_SYMLINK_FOLLOW) !=
          0)
        return false;
      if (::rename(hidden.c_str(), target.c_str()) != 0) {
        const int saved_errno = errno;
        ::unlink(hidden.c_str());
        errno = saved_errno;
        return false;
      }
    }
    ::close(descriptor_);
    descriptor_ = -1;
    return true;
  }
  if (::rename(named_path_.c_str(), target.c_str()) != 0) return false;
  forget_for_interrupts(named_path_.string());
  named_path_.clear();
  return true;
}

void TemporaryFile::remove() noexcept {
  if (descriptor_ >= 0) ::close(descriptor_);  // an unnamed file vanishes with its descriptor
  descriptor_ = -1;
  if (!named_path_.empty()) {
    ::unlink(named_path_.c_str());
    forget_for_interrupts(named_path_.string());
    named_path_.clear();
  }
}

}  // namespace impactbench::output
