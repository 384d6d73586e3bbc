// Contacts copied between slots in the slots' own storage (copy_keeping_storage): every field
// is the source's afterwards, and a slot whose name and blocks are large enough keeps their
// heap storage where it was.
#include <gtest/gtest.h>

#include "lib/model/contact_storage.hpp"

namespace impactbench::model {
namespace {

Contact<double> two_disk_contact(double scale) {
  Contact<double> c;
  c.key = {1234, 5678, 0};
  c.name = "disk1234-disk5678";  // longer than the string's in-object buffer: on the heap
  c.gap = -1e-4 * scale;
  for (int b = 0; b < 2; ++b) {
    JacobianBlock<double> block;
    block.first_velocity = 3 * (b == 0 ? 1234 : 5678);
    block.rows = Eigen::MatrixXd::Constant(2, 3, scale).array() + b;
    block.rows(1, 2) = -scale;
    c.blocks.push_back(block);
  }
  c.normal_drift = 0.25 * scale;
  c.tangent_drift = Eigen::VectorXd::Constant(1, -0.5 * scale);
  c.friction = 0.3 * scale;
  c.restitution = 0.1 * scale;
  c.point = Eigen::Vector3d(1.0, 2.0, 3.0) * scale;
  c.normal = Eigen::Vector3d(0.6, 0.8, 0.0) * scale;
  return c;
}

void expect_same_contact(const Contact<double>& a, const Contact<double>& b) {
  EXPECT_EQ(a.key, b.key);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.gap, b.gap);
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t k = 0; k < a.blocks.size(); ++k) {
    EXPECT_EQ(a.blocks[k].first_velocity, b.blocks[k].first_velocity) << k;
    EXPECT_EQ(a.blocks[k].rows, b.blocks[k].rows) << k;
  }
  EXPECT_EQ(a.normal_drift, b.normal_drift);
  EXPECT_EQ(a.tangent_drift, b.tangent_drift);
  EXPECT_EQ(a.friction, b.friction);
  EXPECT_EQ(a.restitution, b.restitution);
  EXPECT_EQ(a.point, b.point);
  EXPECT_EQ(a.normal, b.normal);
}

TEST(ContactStorage, ACopyHasEveryFieldAndTheSlotKeepsItsStorage) {
  const Contact<double> from = two_disk_contact(2.0);
  Contact<double> slot = two_disk_contact(-7.0);
  slot.key = {3, -1, 1};
  slot.name = "disk3-ground";  // shorter, in the capacity the longer name left
  const char* name_storage = slot.name.data();
  const JacobianBlock<double>* blocks_storage = slot.blocks.data();
  const double* rows_storage[2] = {slot.blocks[0].rows.data(), slot.blocks[1].rows.data()};
  const double* drift_storage = slot.tangent_drift.data();

  copy_keeping_storage(from, slot);
  expect_same_contact(slot, from);
  EXPECT_EQ(slot.name.data(), name_storage);
  EXPECT_EQ(slot.blocks.data(), blocks_storage);
  EXPECT_EQ(slot.blocks[0].rows.data(), rows_storage[0]);
  EXPECT_EQ(slot.blocks[1].rows.data(), rows_storage[1]);
  EXPECT_EQ(slot.tangent_drift.data(), drift_storage);
}

TEST(ContactStorage, ACopyChangesASlotsNumberOfBlocksBothWays) {
  Contact<double> one_body = two_disk_contact(3.0);
  one_body.key = {4, -1, 0};
  one_body.name = "disk4-ground";
  one_body.blocks.pop_back();
  const Contact<double> two_bodies = two_disk_contact(5.0);

  Contact<double> slot = one_body;
  copy_keeping_storage(two_bodies, slot);
  expect_same_contact(slot, two_bodies);
  copy_keeping_storage(one_body, slot);
  expect_same_contact(slot, one_body);
}

}  // namespace
}  // namespace impactbench::model
