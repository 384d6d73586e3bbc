#pragma once
// Software prefetch for loops over many contacts. A contact's Jacobian blocks are a heap array,
// and each block's rows a heap array of their own: two pointers deep, where the hardware
// prefetcher, which follows addresses in sequence, cannot go. On piles of thousands of contacts
// the loops over the contact slots (their evaluation, the active-set test, the assembly of J
// and M⁻¹Jᵀ) waited on these loads more than they computed. A prefetch changes no result.
#include <cstddef>
#include <span>

#include "lib/model/contact.hpp"

namespace impactbench::model {

/// How many contacts ahead the rows are fetched: a few contacts' work covers a memory latency.
inline constexpr std::size_t kContactPrefetchDistance = 4;

/// Before the loop body of contact k: the heap storage that contact k + 2·distance points to
/// (its block array, tangent drift and name), and the rows of contact k + distance's blocks
/// (whose array was asked for distance contacts earlier). Always inlined: GCC 12 takes a
/// function whose only effect is a prefetch for one without effects and drops its calls.
template <typename Scalar>
[[gnu::always_inline]] inline void prefetch_contact_storage(
    std::span<const Contact<Scalar>> contacts, std::size_t k,
    std::size_t distance = kContactPrefetchDistance) {
  if (k + 2 * distance < contacts.size()) {
    const Contact<Scalar>& ahead = contacts[k + 2 * distance];
    __builtin_prefetch(ahead.blocks.data());
    __builtin_prefetch(ahead.tangent_drift.data());
    __builtin_prefetch(ahead.name.data());
  }
  if (k + distance < contacts.size())
    for (const auto& block : contacts[k + distance].blocks) __builtin_prefetch(block.rows.data());
}

}  // namespace impactbench::model
