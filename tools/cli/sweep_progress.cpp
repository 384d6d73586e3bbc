#include "tools/cli/sweep_progress.hpp"

#include <cmath>
#include <iostream>
#include <string>

#include "lib/output/number_text.hpp"

namespace impactbench::cli {

SweepProgress::SweepProgress(std::size_t total, bool shown)
    : total_(total), shown_(shown), start_(Clock::now()), next_(start_) {}

SweepProgress::~SweepProgress() {
  if (printed_) std::cerr << '\n';
}

void SweepProgress::update(std::size_t done, std::size_t failed, bool force) {
  if (!shown_) return;
  const auto now = Clock::now();
  if (!force && now < next_) return;
  next_ = now + std::chrono::milliseconds(250);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
  std::string line = "sweep: " + std::to_string(done) + " of " + std::to_string(total_) +
                     " points, " + std::to_string(failed) + " failed";
  if (rate > 0) {
    line += ", " + output::number_text(std::round(rate * 100) / 100) + " points/s, ETA " +
            output::number_text(std::round(static_cast<double>(total_ - done) / rate)) + " s";
  }
  std::cerr << '\r' << line << "   " << std::flush;
  printed_ = true;
}

}  // namespace impactbench::cli
