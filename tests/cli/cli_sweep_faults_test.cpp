// The faults a sweep survives: a truncated or corrupted result is rerun; a worker killed
// mid-point (SIGKILL) leaves no result and the resume reruns it; Ctrl-C (SIGINT) leaves no
// half-written result and the resume finishes; a point past its time limit is a result
// 'timeout'; a second sweep on the same folder is refused (the lock); a merge refuses a result
// of another spec naming its file and lists the missing points.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/engines/csv_table.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::test_support::CliOutcome;
using impactbench::test_support::read_csv_table;
using impactbench::test_support::read_text;
using impactbench::test_support::run_program;
using impactbench::test_support::TemporaryDirectory;

// Three short points and (with `slow`) one of about a second: bouncing_ball with Moreau-Jean
// at dt 1e-5 over 3 s.
// Three fast points and, when `slow`, a last one at `slow_dt` (1e-5: 300,000 steps).
std::string spec_text(bool slow, const std::string& extra = "",
                      const std::string& slow_dt = "1e-5") {
  return "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\nduration = 3\n" + extra +
         "[grid]\ndt = [1e-3, 2e-3, 4e-3" + (slow ? ", " + slow_dt : std::string()) + "]\n";
}

class SweepFaults : public ::testing::Test {
 protected:
  SweepFaults() : work_("impactbench_sweep_faults"), capture_("impactbench_capture") {}

  fs::path write_spec(const std::string& text, const std::string& name = "spec.toml") {
    std::ofstream(work_.path() / name) << text;
    return work_.path() / name;
  }
  CliOutcome sweep(const fs::path& spec, const std::string& more = "") {
    return run_program(IMPACTBENCH_CLI,
                       "sweep '" + spec.string() + "' --out '" + dir().string() + "' " + more,
                       capture_.path());
  }
  // A shell script run with $P the program, $S the spec and $D the output folder.
  // `seconds`: the limit of the whole script (a sanitizer build under a parallel ctest runs the
  // four points of the slow spec in over a minute).
  CliOutcome shell(const fs::path& spec, const std::string& script, int seconds = 300) {
    return run_program("/bin/sh",
                       "-c 'P=" + std::string(IMPACTBENCH_CLI) + "; S=" + spec.string() +
                           "; D=" + dir().string() + "; " + script + "'",
                       capture_.path(), "", {}, seconds);
  }
  // The pids of the workers alive now whose point has no result: each worker writes
  // "sweep-point ID pid PID" as the first line of DIR/logs/ID.log.
  static std::string live_workers_without_result() {
    return "for f in $D/logs/*.log; do [ -e \"$f\" ] || continue; id=${f##*/}; id=${id%.log}; "
           "p=$(sed -n \"1s/^sweep-point $id pid //p\" \"$f\"); "
           "[ -n \"$p\" ] && [ ! -e $D/points/$id.result ] && kill -0 $p 2>/dev/null && echo $p; "
           "done";
  }
  // Starts the sweep of `spec` with one worker ($s its pid) and waits until the worker of the
  // slow point runs ($w its pid). That worker is the one alive whose point has no result while
  // the three fast points have theirs: no guess from timing, which raced on a fast machine.
  // Exits 99 with a line if it never shows.
  static std::string start_and_find_slow_worker() {
    return "$P sweep $S --out $D --jobs 1 & s=$!; w=; "
           "for i in $(seq 3000); do "
           "n=$(ls $D/points 2>/dev/null | grep -c result$); [ $n -ge 4 ] && break; "
           "[ $n -eq 3 ] && w=$(" +
           live_workers_without_result() +
           "); "
           "[ -n \"$w\" ] && break; sleep 0.02; done; "
           "[ -n \"$w\" ] || { echo no worker of the slow point was seen >&2; "
           "kill $s; wait $s; exit 99; }; ";
  }
  fs::path dir() const { return work_.path() / "out"; }
  std::size_t result_count() const {
    std::size_t n = 0;
    if (fs::is_directory(dir() / "points"))
      for (const auto& entry : fs::directory_iterator(dir() / "points"))
        n += entry.path().extension() == ".result";
    return n;
  }
  std::size_t file_count() const {
    std::size_t n = 0;
    if (fs::is_directory(dir() / "points"))
      for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir() / "points")) ++n;
    return n;
  }

  TemporaryDirectory work_;
  TemporaryDirectory capture_;
};

TEST_F(SweepFaults, TruncatedAndCorruptedResultsAreRerun) {
  const fs::path spec = write_spec(spec_text(false));
  ASSERT_EQ(sweep(spec, "--merge").exit_code, 0);
  const auto before = read_csv_table(dir() / "sweep.csv");
  ASSERT_EQ(before.rows.size(), 3u);
  const fs::path first = dir() / "points" / (before.at(0, "id") + ".result");
  const fs::path second = dir() / "points" / (before.at(1, "id") + ".result");
  const std::string text = read_text(first);
  std::ofstream(first, std::ios::trunc) << text.substr(0, text.size() / 2);
  std::string other = read_text(second);
  other[other.find("steps ") + 6] = '9';  // a figure changed, the checksum not
  std::ofstream(second, std::ios::trunc) << other;
  const auto resume = sweep(spec, "--merge");
  EXPECT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_NE(resume.err.find("truncated"), std::string::npos) << resume.err;
  EXPECT_NE(resume.err.find("corrupted"), std::string::npos) << resume.err;
  EXPECT_NE(resume.out.find("2 points ran (0 failed or timed out), 1 already done"),
            std::string::npos)
      << resume.out;
  const auto after = read_csv_table(dir() / "sweep.csv");
  ASSERT_EQ(after.rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(after.at(i, "steps"), before.at(i, "steps"));
    EXPECT_EQ(after.at(i, "linf_error"), before.at(i, "linf_error"));
  }
  // Everything done: a third run runs nothing.
  const auto again = sweep(spec);
  EXPECT_NE(again.out.find("0 points ran (0 failed or timed out), 3 already done"),
            std::string::npos)
      << again.out;
}

TEST_F(SweepFaults, WorkerKilledMidPointIsRerunOnResume) {
  const fs::path spec = write_spec(spec_text(true));
  // Kill the worker of the slow point (the last) once the three fast results are in.
  const auto killed = shell(spec, start_and_find_slow_worker() + "kill -KILL $w; wait $s");
  EXPECT_EQ(killed.exit_code, 1) << killed.out << killed.err;
  EXPECT_NE(killed.err.find("killed by signal 9; no result (a resume reruns it"), std::string::npos)
      << killed.err;
  EXPECT_EQ(result_count(), 3u);
  EXPECT_EQ(file_count(), 3u);  // no partial file of the killed point
  const auto resume = sweep(spec, "--merge");
  EXPECT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_NE(resume.out.find("1 points ran (0 failed or timed out), 3 already done"),
            std::string::npos)
      << resume.out;
  const auto merged = read_csv_table(dir() / "sweep.csv");
  ASSERT_EQ(merged.rows.size(), 4u);
  EXPECT_EQ(std::stod(merged.at(3, "steps")), 3e5);
}

TEST_F(SweepFaults, InterruptLeavesNoHalfWrittenResultAndResumeFinishes) {
  const fs::path spec = write_spec(spec_text(true));
  // Ctrl-C while the slow point runs.
  const auto interrupted = shell(spec, start_and_find_slow_worker() + "kill -INT $s; wait $s");
  EXPECT_EQ(interrupted.exit_code, 130) << interrupted.out << interrupted.err;
  EXPECT_NE(interrupted.err.find("interrupted; run the same command again to finish"),
            std::string::npos)
      << interrupted.err;
  EXPECT_EQ(result_count(), 3u);
  EXPECT_EQ(file_count(), 3u);
  // No worker is left running.
  const auto workers = shell(spec, live_workers_without_result() + " | wc -l");
  EXPECT_EQ(workers.out, "0\n");
  const auto resume = sweep(spec, "--merge");
  EXPECT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_EQ(read_csv_table(dir() / "sweep.csv").rows.size(), 4u);
}

TEST_F(SweepFaults, PointPastItsTimeLimitIsATimeoutResult) {
  // The limit leaves the fast points (0.1 s each in a release build, about 1 s under the
  // sanitizers) far inside it and the slow one (3,000,000 steps) far past it.
  const fs::path spec = write_spec(spec_text(true, "time_limit = 5\n", "1e-6"));
  const auto outcome = sweep(spec, "--merge --jobs 2");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto merged = read_csv_table(dir() / "sweep.csv");
  ASSERT_EQ(merged.rows.size(), 4u);
  EXPECT_EQ(merged.at(3, "status"), "timeout");
  EXPECT_EQ(merged.at(3, "reason"), "passed its time limit of 5 s");
  EXPECT_EQ(merged.at(3, "steps"), "");
  EXPECT_EQ(merged.at(0, "status"), "ok");
  EXPECT_EQ(std::stod(merged.at(0, "steps")), 3000.0);
  // A timed-out point is a result: the resume does not rerun it.
  EXPECT_NE(sweep(spec).out.find("0 points ran"), std::string::npos);
}

TEST_F(SweepFaults, SecondSweepOnTheSameFolderIsRefused) {
  const fs::path spec = write_spec(spec_text(false));
  const auto outcome = shell(spec,
                             "mkdir -p $D; flock $D/lock sleep 3 & sleep 0.5; "
                             "$P sweep $S --out $D; echo rc=$?; wait");
  EXPECT_NE(outcome.out.find("rc=1"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.err.find("another sweep is writing " + dir().string()), std::string::npos)
      << outcome.err;
  EXPECT_EQ(result_count(), 0u);
}

TEST_F(SweepFaults, MergeRefusesAnotherSpecsResultAndListsMissingPoints) {
  const fs::path spec = write_spec(spec_text(false));
  ASSERT_EQ(sweep(spec).exit_code, 0);
  // The same points at another duration: other hashes.
  const fs::path other = write_spec(
      "scenarios = [\"bouncing_ball\"]\nengines = [\"moreau\"]\nduration = 2\n"
      "[grid]\ndt = [1e-3, 2e-3, 4e-3]\n",
      "other.toml");
  const auto refused =
      run_program(IMPACTBENCH_CLI, "merge '" + other.string() + "' --out '" + dir().string() + "'",
                  capture_.path());
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find(".result was written for another spec, setting or program version"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(dir() / "sweep.csv"));
  // One result removed: the merge writes the others and lists it.
  const auto table_before =
      run_program(IMPACTBENCH_CLI, "merge '" + spec.string() + "' --out '" + dir().string() + "'",
                  capture_.path());
  ASSERT_EQ(table_before.exit_code, 0) << table_before.err;
  const auto rows = read_csv_table(dir() / "sweep.csv");
  ASSERT_EQ(rows.rows.size(), 3u);
  fs::remove(dir() / "points" / (rows.at(1, "id") + ".result"));
  const auto missing =
      run_program(IMPACTBENCH_CLI, "merge '" + spec.string() + "' --out '" + dir().string() + "'",
                  capture_.path());
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("1 points have no result:\n  " + rows.at(1, "id") +
                             "  scenario=bouncing_ball; engine=moreau; dt=0.002"),
            std::string::npos)
      << missing.err;
  EXPECT_EQ(read_csv_table(dir() / "sweep.csv").rows.size(), 2u);
}

}  // namespace
