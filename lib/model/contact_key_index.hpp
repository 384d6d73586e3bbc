#pragma once
// Finds contacts by key in time linear in their number: the time stepper looks up, for every
// candidate of a step, the previous step's impulse (warm start) and whether it was a candidate
// then (late contacts). Keys are filed in hash buckets by a counting sort, so building needs no
// comparison sort and, once the buffers have grown, no allocation; a lookup scans one bucket.
#include <span>
#include <vector>

#include "lib/model/contact.hpp"

namespace impactbench::model {

class ContactKeyIndex {
 public:
  /// Files `keys` (any order; a repeated key is found at its first position). Replaces what was
  /// filed before.
  void build(std::span<const ContactKey> keys);
  /// Position of `key` in the keys given to build, or -1.
  int find(const ContactKey& key) const;
  /// The same, trying the kHintWindow positions from `hint` first: a caller that looks keys up
  /// in about the order they were filed (the position after its last find) reads the keys in
  /// sequence instead of through the buckets, also past the few keys it does not look up (the
  /// time stepper looks up only some of its contacts). Any hint gives find(key)'s answer.
  int find(const ContactKey& key, int hint) const;
  static constexpr std::size_t kHintWindow = 8;
  bool contains(const ContactKey& key) const { return find(key) >= 0; }
  void clear() { build(std::span<const ContactKey>()); }
  std::size_t size() const { return keys_.size(); }

 private:
  std::size_t bucket_of(const ContactKey& key) const;
  /// The key of entry e (a position in entries_).
  const ContactKey& filed_key(int e) const {
    return keys_[static_cast<std::size_t>(entries_[static_cast<std::size_t>(e)])];
  }

  std::vector<ContactKey> keys_;   // as given
  std::vector<int> bucket_start_;  // bucket b holds entries_[bucket_start_[b], [b + 1])
  std::vector<int> entries_;       // positions in keys_, by bucket, ascending within one
  std::vector<char> first_;        // position → 1 if its key is not filed before it
};

}  // namespace impactbench::model
