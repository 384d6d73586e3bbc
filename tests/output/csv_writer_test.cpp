// The trajectory and events CSV writers: exact headers, numbers that read back bit for bit
// (the shortest exact text), RFC 4180 quoting, and atomicity: until commit() the target does not
// exist (or keeps its old content) and a failure leaves neither the target nor a temporary file
// behind.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>  // pipe, read, close

#include <gtest/gtest.h>

#include "lib/output/atomic_file.hpp"
#include "lib/output/column_names.hpp"
#include "lib/output/events_csv.hpp"
#include "lib/output/run_outputs.hpp"
#include "lib/output/trajectory_csv.hpp"
#include "tests/support/lib/double_bits.hpp"

namespace impactbench::output {
namespace {

namespace fs = std::filesystem;

class CsvWriter : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "impactbench_csv_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    directory_ = pattern;
  }
  void TearDown() override { fs::remove_all(directory_); }

  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_))
      names.push_back(entry.path().filename().string());
    return names;
  }
  static std::string read(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path directory_;
};

Trajectory two_body_trajectory() {
  Trajectory trajectory;
  trajectory.position_names = {"a.x", "a.y", "a.theta"};
  trajectory.velocity_names = {"a.vx", "a.vy", "a.omega"};
  for (int i = 0; i < 3; ++i) {
    TrajectorySample sample;
    sample.t = 0.1 * i;
    sample.q = Eigen::Vector3d(1.0 / 3.0, -2.5e-300, 0.1 * i);
    sample.v = Eigen::Vector3d(M_PI, -0.0, 1e300);
    sample.energy = 9.81 / 7.0;
    trajectory.samples.push_back(sample);
  }
  return trajectory;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
  return cells;
}

TEST_F(CsvWriter, TrajectoryHeaderAndNumbersRoundTripExactly) {
  const auto trajectory = two_body_trajectory();
  const fs::path path = directory_ / "traj.csv";
  write_trajectory_csv(path, trajectory);
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,a.x,a.y,a.theta,a.vx,a.vy,a.omega,energy");
  for (const auto& sample : trajectory.samples) {
    ASSERT_TRUE(std::getline(in, line));
    const auto cells = split(line);
    ASSERT_EQ(cells.size(), 8u);
    std::vector<double> expected{sample.t};
    for (const double q : sample.q) expected.push_back(q);
    for (const double v : sample.v) expected.push_back(v);
    expected.push_back(sample.energy);
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const double value = std::strtod(cells[c].c_str(), nullptr);
      EXPECT_EQ(test_support::bits(value), test_support::bits(expected[c])) << cells[c];
    }
  }
  EXPECT_FALSE(std::getline(in, line));
  EXPECT_EQ(files(), std::vector<std::string>{"traj.csv"});  // no temporary left
}

TEST_F(CsvWriter, EventsHeaderRowsAndQuoting) {
  const fs::path path = directory_ / "events.csv";
  write_events_csv(path, {{0.5, "ball-ground", "impact", "open", "stick", 4.2, -0.25},
                          {1.0, "C_L, corner \"1\"", "slip", "stick", "slip", 0.0, 0.0}});
  EXPECT_EQ(read(path),
            "t,contact,kind,from_mode,to_mode,impulse_n,impulse_t\n"
            "0.5,ball-ground,impact,open,stick,4.2,-0.25\n"
            "1,\"C_L, corner \"\"1\"\"\",slip,stick,slip,0,0\n");
}

TEST_F(CsvWriter, NothingAppearsBeforeCommitAndNothingStaysWithoutIt) {
  const fs::path path = directory_ / "traj.csv";
  {
    TrajectoryCsvWriter writer(path, {"a.x"}, {"a.vx"});
    writer.write_row(0.0, Eigen::VectorXd::Ones(1), Eigen::VectorXd::Ones(1), 1.0);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(files().empty());  // the temporary has no name (O_TMPFILE) until the commit
  }                                // destroyed without commit, as when an engine throws
  EXPECT_TRUE(files().empty());
}

TEST_F(CsvWriter, AFailureHalfwayLeavesNoFile) {
  auto trajectory = two_body_trajectory();
  trajectory.samples[2].v = Eigen::VectorXd::Zero(2);  // inconsistent row: the writer throws
  EXPECT_THROW(write_trajectory_csv(directory_ / "traj.csv", trajectory), std::invalid_argument);
  EXPECT_TRUE(files().empty());
}

TEST_F(CsvWriter, AnExistingFileIsReplacedOnlyOnSuccess) {
  const fs::path path = directory_ / "events.csv";
  std::ofstream(path) << "previous results\n";
  try {
    EventsCsvWriter writer(path);
    writer.write_row({0.1, "c", "impact", "open", "open", 1.0, 0.0});
    EXPECT_EQ(read(path), "previous results\n");
    throw std::runtime_error("engine failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read(path), "previous results\n");
  EXPECT_EQ(files(), std::vector<std::string>{"events.csv"});
  write_events_csv(path, {});
  EXPECT_EQ(read(path), "t,contact,kind,from_mode,to_mode,impulse_n,impulse_t\n");
}

TEST_F(CsvWriter, MissingDirectoryAndDoubleCommitAreErrors) {
  EXPECT_THROW(AtomicFile(directory_ / "no" / "such" / "dir.csv"), std::runtime_error);
  AtomicFile file(directory_ / "x.csv");
  file.stream() << "x\n";
  file.commit();
  EXPECT_THROW(file.commit(), std::logic_error);
  EXPECT_EQ(read(directory_ / "x.csv"), "x\n");
}

TEST_F(CsvWriter, APipeBehindAProcLinkIsWrittenThrough) {
  // /dev/stdout is a link to /proc/self/fd/1, whose own link text for a pipe is "pipe:[N]".
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  const fs::path proc_link = "/proc/self/fd/" + std::to_string(ends[1]);
  const fs::path user_link = directory_ / "stdout";
  fs::create_symlink(proc_link, user_link);
  {
    AtomicFile file(user_link);
    file.stream() << "through the pipe\n";
    file.commit();
  }
  ::close(ends[1]);
  char buffer[64] = {};
  const ssize_t got = ::read(ends[0], buffer, sizeof buffer - 1);
  ::close(ends[0]);
  EXPECT_EQ(std::string(buffer, got > 0 ? static_cast<std::size_t>(got) : 0u),
            "through the pipe\n");
  EXPECT_EQ(files(), std::vector<std::string>{"stdout"});  // the link only, no temporary
}

TEST_F(CsvWriter, AFailedSecondOutputLeavesNoFirst) {
  const auto trajectory = two_body_trajectory();
  const std::vector<EventRecord> events{{0.25, "a-ground", "impact", "open", "stick", 1.5, 0.0}};
  // /dev/full accepts the open and fails every write with ENOSPC: the events cannot be written,
  // so the trajectory (committed first before) must not appear.
  ASSERT_TRUE(fs::exists("/dev/full"));
  EXPECT_THROW(write_run_outputs(trajectory, events, directory_ / "traj.csv", "/dev/full"),
               std::runtime_error);
  EXPECT_TRUE(files().empty());
  // Nor when the trajectory is the one that fails.
  EXPECT_THROW(write_run_outputs(trajectory, events, "/dev/full", directory_ / "ev.csv"),
               std::runtime_error);
  EXPECT_TRUE(files().empty());
}

TEST_F(CsvWriter, RunOutputsAreAllOrNothing) {
  const auto trajectory = two_body_trajectory();
  const std::vector<EventRecord> events{{0.25, "a-ground", "impact", "open", "stick", 1.5, 0.0}};
  // The events file cannot be created: the trajectory must not appear either.
  EXPECT_THROW(write_run_outputs(trajectory, events, directory_ / "traj.csv",
                                 directory_ / "missing" / "events.csv"),
               std::runtime_error);
  EXPECT_TRUE(files().empty());
  // A bad trajectory row: no events file either.
  auto broken = trajectory;
  broken.samples[1].q.resize(1);
  EXPECT_THROW(write_run_outputs(broken, events, directory_ / "traj.csv", directory_ / "ev.csv"),
               std::invalid_argument);
  EXPECT_TRUE(files().empty());
  write_run_outputs(trajectory, events, directory_ / "traj.csv", directory_ / "ev.csv");
  auto names = files();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"ev.csv", "traj.csv"}));
  EXPECT_EQ(read(directory_ / "ev.csv"),
            "t,contact,kind,from_mode,to_mode,impulse_n,impulse_t\n0.25,a-ground,impact,open,stick,"
            "1.5,0\n");
}

TEST(ColumnNames, PlanarAndSpatialOrder) {
  std::vector<model::BodySpec> bodies(2);
  bodies[0].name = "ball";
  bodies[1].name = "box";
  EXPECT_EQ(
      rigid_body_position_names(bodies, false),
      (std::vector<std::string>{"ball.x", "ball.y", "ball.theta", "box.x", "box.y", "box.theta"}));
  EXPECT_EQ(rigid_body_velocity_names(bodies, false),
            (std::vector<std::string>{"ball.vx", "ball.vy", "ball.omega", "box.vx", "box.vy",
                                      "box.omega"}));
  EXPECT_EQ(rigid_body_position_names({bodies[0]}, true),
            (std::vector<std::string>{"ball.x", "ball.y", "ball.z", "ball.qw", "ball.qx", "ball.qy",
                                      "ball.qz"}));
  EXPECT_EQ(
      rigid_body_velocity_names({bodies[0]}, true),
      (std::vector<std::string>{"ball.vx", "ball.vy", "ball.vz", "ball.wx", "ball.wy", "ball.wz"}));
}

}  // namespace
}  // namespace impactbench::output
