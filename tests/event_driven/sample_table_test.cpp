// The event-driven run's flat sample table: what goes in comes back, sample by sample and bit
// for bit; a reserved table does not move its samples; a sample of the wrong size is refused.
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/sample_table.hpp"

namespace impactbench::engines::event_driven {
namespace {

// Sample k of a table of 2 positions and 3 velocities, with values that differ everywhere.
Eigen::VectorXd positions(int k) {
  return Eigen::Vector2d(k + 0.1, -k - 0.2);
}
Eigen::VectorXd velocities(int k) {
  return Eigen::Vector3d(k * 1e-3, k + 1e300, -k / 3.0);
}

TEST(SampleTable, GivesBackEverySampleAsItWasAppended) {
  SampleTable table;
  table.set_sizes(2, 3);
  constexpr int kCount = 1000;  // past any initial capacity: the storage grows several times
  for (int k = 0; k < kCount; ++k)
    table.push_back(0.01 * k, positions(k), velocities(k), 1.0 / (k + 1));
  ASSERT_EQ(table.size(), static_cast<std::size_t>(kCount));
  EXPECT_EQ(table.position_size(), 2);
  EXPECT_EQ(table.velocity_size(), 3);
  for (int k = 0; k < kCount; ++k) {
    const SampleView s = table[static_cast<std::size_t>(k)];
    EXPECT_EQ(s.t, 0.01 * k);
    EXPECT_EQ(s.q, positions(k)) << "sample " << k;
    EXPECT_EQ(s.v, velocities(k)) << "sample " << k;
    EXPECT_EQ(s.energy, 1.0 / (k + 1));
  }
  EXPECT_EQ(table.front().t, 0.0);
  EXPECT_EQ(table.back().v, velocities(kCount - 1));
}

TEST(SampleTable, IteratesInOrder) {
  SampleTable table;
  table.set_sizes(2, 3);
  for (int k = 0; k < 5; ++k) table.push_back(k, positions(k), velocities(k), 0.0);
  std::vector<double> times;
  for (const SampleView& s : table) {
    EXPECT_EQ(s.q, positions(static_cast<int>(times.size())));
    times.push_back(s.t);
  }
  EXPECT_EQ(times, (std::vector<double>{0, 1, 2, 3, 4}));
}

TEST(SampleTable, AReservedTableKeepsItsSamplesInPlace) {
  SampleTable table;
  table.set_sizes(2, 3);
  table.reserve(300);
  table.push_back(0.0, positions(0), velocities(0), 0.0);
  const double* first = table.front().q.data();
  for (int k = 1; k < 300; ++k) table.push_back(k, positions(k), velocities(k), 0.0);
  EXPECT_EQ(table.front().q.data(), first);
  table.clear();  // sizes and storage stay
  EXPECT_TRUE(table.empty());
  table.push_back(7.0, positions(7), velocities(7), 0.0);
  EXPECT_EQ(table.front().q.data(), first);
  EXPECT_EQ(table.front().v, velocities(7));
}

TEST(SampleTable, RefusesASampleOfTheWrongSizeAndKeepsWhatItHad) {
  SampleTable table;
  table.set_sizes(2, 3);
  table.push_back(0.0, positions(0), velocities(0), 0.0);
  EXPECT_THROW(table.push_back(1.0, velocities(1), velocities(1), 0.0), std::invalid_argument);
  EXPECT_THROW(table.push_back(1.0, positions(1), positions(1), 0.0), std::invalid_argument);
  ASSERT_EQ(table.size(), 1u);
  EXPECT_EQ(table.back().v, velocities(0));
  EXPECT_THROW(table.set_sizes(-1, 3), std::invalid_argument);
}

TEST(SampleTable, SetSizesEmptiesTheTable) {
  SampleTable table;
  table.set_sizes(2, 3);
  table.push_back(0.0, positions(0), velocities(0), 0.0);
  table.set_sizes(3, 2);
  EXPECT_TRUE(table.empty());
  table.push_back(0.0, velocities(4), positions(4), 2.0);
  EXPECT_EQ(table.front().q, velocities(4));
  EXPECT_EQ(table.front().v, positions(4));
}

}  // namespace
}  // namespace impactbench::engines::event_driven
