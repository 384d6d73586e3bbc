#pragma once
// The systems write their contacts over the slots of the caller's vector, each slot's name and
// Jacobian blocks keeping their storage. A search finds a different number of contacts each
// time: the slots a shorter search cuts off go to a spare pool (per thread and scalar type) and
// come back for a longer one, so that a search whose count goes up and down allocates nothing
// once it has reached its largest count.
#include <cstddef>
#include <vector>

#include "lib/model/contact.hpp"

namespace impactbench::model {

namespace contact_storage_detail {
template <typename Scalar>
std::vector<Contact<Scalar>>& spare_contacts() {
  thread_local std::vector<Contact<Scalar>> spare;
  return spare;
}
}  // namespace contact_storage_detail

/// Cuts or extends `contacts` to `count` slots (spare ones first when it extends).
template <typename Scalar>
void resize_contacts(std::vector<Contact<Scalar>>& contacts, std::size_t count) {
  auto& spare = contact_storage_detail::spare_contacts<Scalar>();
  while (contacts.size() > count) {
    spare.push_back(std::move(contacts.back()));
    contacts.pop_back();
  }
  while (contacts.size() < count && !spare.empty()) {
    contacts.push_back(std::move(spare.back()));
    spare.pop_back();
  }
  contacts.resize(count);
}

/// Appends one slot (a spare one if there is) and returns it.
template <typename Scalar>
Contact<Scalar>& append_contact(std::vector<Contact<Scalar>>& contacts) {
  resize_contacts(contacts, contacts.size() + 1);
  return contacts.back();
}

}  // namespace impactbench::model
