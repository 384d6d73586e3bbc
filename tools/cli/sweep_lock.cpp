#include "tools/cli/sweep_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "tools/cli/command.hpp"

namespace impactbench::cli {

SweepLock::SweepLock(const std::filesystem::path& dir, bool shared) {
  const std::filesystem::path path = dir / "lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw CliError("sweep: cannot open " + path.string() + ": " + std::strerror(errno),
                   kExitFailure);
  if (::flock(fd_, (shared ? LOCK_SH : LOCK_EX) | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    throw CliError(error == EWOULDBLOCK
                       ? "sweep: another sweep is writing " + dir.string() + " (" + path.string() +
                             " is locked); wait for it to end"
                       : "sweep: cannot lock " + path.string() + ": " + std::strerror(error),
                   kExitFailure);
  }
}

SweepLock::~SweepLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace impactbench::cli
