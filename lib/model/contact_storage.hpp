#pragma once
// The systems write their contacts over the slots of the caller's vector, each slot's name and
// Jacobian blocks keeping their storage. A search finds a different number of contacts each
// time, and a slot's contact may have one body block or two: the slots and blocks a shorter
// search cuts off go to a spare pool (per thread and type) and come back for a longer one, so
// that a search whose counts go up and down allocates nothing once it has reached its largest
// counts.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/model/contact.hpp"

namespace impactbench::model {

namespace contact_storage_detail {
template <typename Item>
std::vector<Item>& spares() {
  thread_local std::vector<Item> spare;
  return spare;
}

/// Cuts or extends `items` to `count` (spare ones first when it extends); the cut ones, with
/// their heap storage, go to the spare pool.
template <typename Item>
void resize_keeping_storage(std::vector<Item>& items, std::size_t count) {
  auto& spare = spares<Item>();
  while (items.size() > count) {
    spare.push_back(std::move(items.back()));
    items.pop_back();
  }
  while (items.size() < count && !spare.empty()) {
    items.push_back(std::move(spare.back()));
    spare.pop_back();
  }
  items.resize(count);
}
}  // namespace contact_storage_detail

/// Cuts or extends `contacts` to `count` slots (spare ones first when it extends).
template <typename Scalar>
void resize_contacts(std::vector<Contact<Scalar>>& contacts, std::size_t count) {
  contact_storage_detail::resize_keeping_storage(contacts, count);
}

/// Appends one slot (a spare one if there is) and returns it.
template <typename Scalar>
Contact<Scalar>& append_contact(std::vector<Contact<Scalar>>& contacts) {
  resize_contacts(contacts, contacts.size() + 1);
  return contacts.back();
}

/// Cuts or extends a contact's Jacobian blocks to `count` (one body or two), spare blocks
/// first: a slot whose contact went from two bodies to one and back kept reallocating the
/// second block's rows (97 of the 129 allocations per step of a 1,000-disk pile).
template <typename Scalar>
void resize_blocks(std::vector<JacobianBlock<Scalar>>& blocks, std::size_t count) {
  contact_storage_detail::resize_keeping_storage(blocks, count);
}

namespace contact_storage_detail {
/// Contact's fields as copy_keeping_storage copies them, in Contact's order: the size check
/// compares the two layouts, so it holds with any standard library.
struct CopiedContactFields {
  ContactKey key;
  std::string name;
  double gap;
  std::vector<JacobianBlock<double>> blocks;
  double normal_drift;
  Eigen::VectorXd tangent_drift;
  double friction;
  double restitution;
  Eigen::Vector3d point;
  Eigen::Vector3d normal;
};
}  // namespace contact_storage_detail

/// Writes `from` over `to` in `to`'s own storage (its name, blocks and rows kept where their
/// sizes allow): a contact copied between slots leaves each slot's heap storage where it was,
/// which a swap would trade between the slots. Every field of Contact is copied; the size check
/// below is there so that a field added to Contact is added here too.
template <typename Scalar>
void copy_keeping_storage(const Contact<Scalar>& from, Contact<Scalar>& to) {
  static_assert(sizeof(Contact<double>) == sizeof(contact_storage_detail::CopiedContactFields),
                "a field was added to Contact: copy it here, and list it above");
  to.key = from.key;
  to.name.assign(from.name);
  to.gap = from.gap;
  if (to.blocks.size() != from.blocks.size()) resize_blocks(to.blocks, from.blocks.size());
  for (std::size_t b = 0; b < from.blocks.size(); ++b) {
    to.blocks[b].first_velocity = from.blocks[b].first_velocity;
    to.blocks[b].rows = from.blocks[b].rows;
  }
  to.normal_drift = from.normal_drift;
  to.tangent_drift = from.tangent_drift;
  to.friction = from.friction;
  to.restitution = from.restitution;
  to.point = from.point;
  to.normal = from.normal;
}

}  // namespace impactbench::model
