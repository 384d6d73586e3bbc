// The published metrics on synthetic tosses: a toss against itself scores 0, known offsets give
// their hand-computed values, and the statistics over tosses.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "lib/validation/score_statistics.hpp"
#include "lib/validation/toss_score.hpp"

namespace impactbench::validation {
namespace {

constexpr double kSide = 0.1048;

// A tumbling fall onto the board: five samples 0.1 s apart, the last two touching.
Toss synthetic_toss() {
  Toss toss{"synthetic", {}};
  const double heights[] = {0.3, 0.25, 0.15, 0.055, 0.0524};
  for (int k = 0; k < 5; ++k) {
    TossSample s;
    s.t = 0.1 * k;
    s.position = {0.1 * k, -0.05 * k, heights[k]};
    s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.2 * k, Eigen::Vector3d(1, 2, 2) / 3));
    s.velocity = {1.0, -0.5, -1.0 + 0.1 * k};
    s.angular_velocity_body = {0.5 * k, 1.0, -2.0};
    toss.samples.push_back(s);
  }
  return toss;
}

std::vector<SimulatedPose> as_simulated(const Toss& toss, std::size_t start) {
  std::vector<SimulatedPose> poses;
  for (std::size_t k = start; k < toss.samples.size(); ++k) {
    const TossSample& s = toss.samples[k];
    poses.push_back({s.position, s.orientation, s.velocity, s.angular_velocity_world()});
  }
  return poses;
}

TEST(TossScore, ATossScoredAgainstItselfIsZero) {
  const Toss toss = synthetic_toss();
  for (const std::size_t start : {0u, 2u}) {
    const TossScore score = score_toss(toss, start, as_simulated(toss, start), CubeGeometry{});
    for (const double value : score_values(score)) EXPECT_EQ(value, 0.0);
  }
  EXPECT_EQ(score_names().size(), score_values(TossScore{}).size());
}

TEST(TossScore, KnownOffsetsGiveTheirValues) {
  const Toss toss = synthetic_toss();
  std::vector<SimulatedPose> sim = as_simulated(toss, 0);
  // Every state: position off by (0.003, 0, 0.004) (5 mm), rotated a further 0.3 rad about an
  // axis of its own, velocity off by (0, 0.6, 0.8) (1 m/s), angular velocity by (2, 0, 0).
  const Eigen::Quaterniond offset(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0, 0.6, 0.8)));
  for (auto& pose : sim) {
    pose.position += Eigen::Vector3d(0.003, 0, 0.004);
    pose.orientation = offset * pose.orientation;
    pose.velocity += Eigen::Vector3d(0, 0.6, 0.8);
    pose.angular_velocity += Eigen::Vector3d(2, 0, 0);
  }
  // The other quaternion of the last rotation: the same pose (double cover).
  sim.back().orientation.coeffs() *= -1;
  const TossScore score = score_toss(toss, 0, sim, CubeGeometry{});
  EXPECT_NEAR(score.position, 0.005 / kSide, 1e-15);
  EXPECT_NEAR(score.rotation, 0.3, 1e-14);
  EXPECT_NEAR(score.velocity, 1.0, 1e-15);
  EXPECT_NEAR(score.angular_velocity, 2.0, 1e-15);
  EXPECT_NEAR(score.rest_position, 0.005, 1e-15);
  EXPECT_NEAR(score.rest_rotation, 0.3, 1e-14);
}

TEST(TossScore, FirstContactTimeAndPerSampleAverage) {
  const Toss toss = synthetic_toss();
  // The data's lowest corner reaches the margin at sample 3 (t = 0.3). A simulation whose cube
  // is 0.1 m lower at samples 2..4 (0.05 m below the board at sample 2's corner) touches at
  // t = 0.2; its position error is 0.1 m at 3 of 5 samples: mean 0.06 m = 0.06/side.
  std::vector<SimulatedPose> sim = as_simulated(toss, 0);
  for (std::size_t k = 2; k < 5; ++k) sim[k].position.z() -= 0.1;
  const TossScore score = score_toss(toss, 0, sim, CubeGeometry{});
  EXPECT_NEAR(score.first_contact_time, 0.1, 1e-15);
  EXPECT_NEAR(score.position, 0.06 / kSide, 1e-14);
  EXPECT_NEAR(score.rest_position, 0.1, 1e-15);
  // A simulation that never touches counts the last sample's time: |0.4 − 0.3|.
  sim = as_simulated(toss, 0);
  for (auto& pose : sim) pose.position.z() += 1.0;
  EXPECT_NEAR(score_toss(toss, 0, sim, CubeGeometry{}).first_contact_time, 0.1, 1e-15);
  EXPECT_THROW(score_toss(toss, 1, sim, CubeGeometry{}), std::invalid_argument);
}

TEST(TossScore, SampleErrorsAreThePerSampleTermsOfTheMeans) {
  // A simulation from sample 1: 0.1 m low at samples 2..4, and turned
  // 0.25 rad further at sample 4 only. Its errors, at times 0, 0.1, 0.2, 0.3 since sample 1,
  // are 0, 0.1, 0.1, 0.1 m (in sides) and 0, 0, 0, 0.25 rad.
  const Toss toss = synthetic_toss();
  std::vector<SimulatedPose> sim = as_simulated(toss, 1);
  for (std::size_t k = 1; k < 4; ++k) sim[k].position.z() -= 0.1;
  sim[3].orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.25, Eigen::Vector3d::UnitX())) * sim[3].orientation;
  const auto errors = sample_errors(toss, 1, sim, CubeGeometry{});
  ASSERT_EQ(errors.size(), 4u);
  const double position[] = {0, 0.1 / kSide, 0.1 / kSide, 0.1 / kSide};
  const double rotation[] = {0, 0, 0, 0.25};
  for (std::size_t i = 0; i < errors.size(); ++i) {
    EXPECT_NEAR(errors[i].time, 0.1 * static_cast<double>(i), 1e-15);
    EXPECT_NEAR(errors[i].position, position[i], 1e-14);
    EXPECT_NEAR(errors[i].rotation, rotation[i], 1e-14);
  }
  const TossScore score = score_toss(toss, 1, sim, CubeGeometry{});
  EXPECT_NEAR(score.position, 0.3 / kSide / 4, 1e-14);
  EXPECT_NEAR(score.rotation, 0.25 / 4, 1e-14);
  EXPECT_THROW(sample_errors(toss, 0, sim, CubeGeometry{}), std::invalid_argument);
}

TEST(TossScore, TrajectoryColumnsAreReadAndInterpolatedAtTheSampleTimes) {
  // A simulation of a body "cube" from sample 1 (t = 0.1) on, sampled every 0.05 s: its
  // state at data time t is read at simulated time t − 0.1.
  const Toss toss = synthetic_toss();
  output::Trajectory trajectory;
  trajectory.position_names = {"cube.x",  "cube.y",  "cube.z", "cube.qw",
                               "cube.qx", "cube.qy", "cube.qz"};
  trajectory.velocity_names = {"cube.vx", "cube.vy", "cube.vz", "cube.wx", "cube.wy", "cube.wz"};
  for (int i = 0; i <= 8; ++i) {
    output::TrajectorySample s;
    s.t = 0.05 * i;
    s.q.resize(7);
    // x = t, z = 1; the quaternion alternates its sign (the same rotation about z, 0.1 t rad).
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.1 * s.t, Eigen::Vector3d::UnitZ()));
    const double sign = i % 2 ? -1.0 : 1.0;
    s.q << s.t, 0, 1, sign * q.w(), sign * q.x(), sign * q.y(), sign * q.z();
    s.v.resize(6);
    s.v << 1, 0, 0, 0, 0, 2 * s.t;
    trajectory.samples.push_back(s);
  }
  const auto poses = poses_at_samples(trajectory, "cube", toss, 1);
  ASSERT_EQ(poses.size(), 4u);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const double t = 0.1 * static_cast<double>(i);
    EXPECT_NEAR(poses[i].position.x(), t, 1e-15);
    EXPECT_NEAR(poses[i].angular_velocity.z(), 2 * t, 1e-15);
    EXPECT_NEAR(Eigen::AngleAxisd(poses[i].orientation).angle(), 0.1 * t, 1e-12);
  }
  EXPECT_THROW(poses_at_samples(trajectory, "ball", toss, 1), std::invalid_argument);
}

TEST(ScoreStatistics, MeanMedianAndNinetiethPercentile) {
  // Sorted 1, 2, 3, 4, 10: mean 4; median 3; p90 at position 0.9·4 = 3.6: 4 + 0.6·6 = 7.6.
  const Statistics s = statistics({10, 2, 4, 1, 3});
  EXPECT_EQ(s.count, 5);
  EXPECT_EQ(s.mean, 4.0);
  EXPECT_EQ(s.median, 3.0);
  EXPECT_NEAR(s.p90, 7.6, 1e-15);
  EXPECT_EQ(percentile({5}, 0.9), 5.0);
  EXPECT_EQ(percentile({1, 2}, 0.5), 1.5);
  EXPECT_TRUE(std::isnan(statistics({}).mean));
  EXPECT_EQ(statistics({}).count, 0);
}

}  // namespace
}  // namespace impactbench::validation
