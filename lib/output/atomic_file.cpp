#include "lib/output/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <stdlib.h>  // mkstemp (POSIX)
#include <unistd.h>  // close

namespace impactbench::output {

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  const auto directory = target_.has_parent_path() ? target_.parent_path() : ".";
  // Hidden, unique name next to the target: ".<name>.XXXXXX".
  std::string hidden_name(".");
  hidden_name.append(target_.filename().string()).append(".XXXXXX");
  const std::string pattern = (directory / hidden_name).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int descriptor = ::mkstemp(name.data());
  if (descriptor < 0)
    throw std::runtime_error("cannot write " + target_.string() + ": " + std::strerror(errno));
  ::close(descriptor);
  temporary_ = name.data();
  stream_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!stream_) {
    discard();
    throw std::runtime_error("cannot write " + target_.string() + ": cannot open a temporary file");
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

void AtomicFile::commit() {
  if (done_) throw std::logic_error("AtomicFile::commit called twice for " + target_.string());
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail()) {
    discard();
    throw std::runtime_error("cannot write " + target_.string() + ": write failed");
  }
  std::error_code error;
  std::filesystem::rename(temporary_, target_, error);
  if (error) {
    discard();
    throw std::runtime_error("cannot write " + target_.string() + ": " + error.message());
  }
  done_ = true;
}

}  // namespace impactbench::output
