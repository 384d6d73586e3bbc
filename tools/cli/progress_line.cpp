#include "tools/cli/progress_line.hpp"

#include <unistd.h>  // isatty

#include <algorithm>
#include <cstdio>

#include "lib/output/number_text.hpp"

namespace impactbench::cli {

namespace {
constexpr std::chrono::seconds kQuietStart(3);              // a run shorter than this shows none
constexpr std::chrono::milliseconds kRefreshInterval(500);  // between two rewrites of the line
}  // namespace

ProgressLine::ProgressLine(std::string label, double duration, bool from_start)
    : label_(std::move(label)),
      duration_(duration),
      start_(Clock::now()),
      next_print_(from_start ? start_ : start_ + kQuietStart) {}

ProgressLine::~ProgressLine() {
  if (shown_) std::fputc('\n', stderr);
}

void ProgressLine::update(double t) {
  const Clock::time_point now = Clock::now();
  if (now < next_print_) return;
  next_print_ = now + kRefreshInterval;
  shown_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = duration_ > 0.0 ? std::clamp(t / duration_, 0.0, 1.0) : 0.0;
  // Whole seconds and percent: the line is for a person watching; \r rewrites it in place.
  std::fprintf(stderr, "\r%s: t = %s of %s s (%d%%), %lld s elapsed", label_.c_str(),
               output::number_text(t).c_str(), output::number_text(duration_).c_str(),
               static_cast<int>(100.0 * fraction), static_cast<long long>(elapsed));
  std::fflush(stderr);
}

bool ProgressLine::stderr_is_terminal() {
  return ::isatty(STDERR_FILENO) == 1;
}

}  // namespace impactbench::cli
