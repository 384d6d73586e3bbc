#include "lib/model/contact_key_index.hpp"

#include <algorithm>
#include <cstdint>

#include "lib/model/growing_capacity.hpp"

namespace impactbench::model {

std::size_t ContactKeyIndex::bucket_of(const ContactKey& key) const {
  // Multiplicative hashing of the three fields; the bucket count is a power of two.
  const auto mix =
      static_cast<std::uint64_t>(static_cast<std::uint32_t>(key.body_a)) * 0x9E3779B97F4A7C15ull ^
      static_cast<std::uint64_t>(static_cast<std::uint32_t>(key.body_b)) * 0xC2B2AE3D27D4EB4Full ^
      static_cast<std::uint64_t>(static_cast<std::uint32_t>(key.feature)) * 0x165667B19E3779F9ull;
  return static_cast<std::size_t>((mix ^ (mix >> 29)) & (bucket_start_.size() - 2));
}

void ContactKeyIndex::build(std::span<const ContactKey> keys) {
  reserve_growing(keys_, keys.size());
  keys_.assign(keys.begin(), keys.end());
  std::size_t buckets = 1;
  while (buckets < keys_.size()) buckets *= 2;  // about one key per bucket
  reserve_growing(bucket_start_, buckets + 1);
  bucket_start_.assign(buckets + 1, 0);
  for (const ContactKey& key : keys_) ++bucket_start_[bucket_of(key) + 1];
  for (std::size_t b = 0; b < buckets; ++b) bucket_start_[b + 1] += bucket_start_[b];
  reserve_growing(entries_, keys_.size());
  entries_.resize(keys_.size());
  // Filled from the back so that each bucket keeps its keys in ascending position.
  for (std::size_t k = keys_.size(); k-- > 0;)
    entries_[static_cast<std::size_t>(--bucket_start_[bucket_of(keys_[k]) + 1])] =
        static_cast<int>(k);
  // bucket_start_[b + 1] now marks bucket b's start; shift back to starts at [b].
  for (std::size_t b = 0; b < buckets; ++b) bucket_start_[b] = bucket_start_[b + 1];
  bucket_start_[buckets] = static_cast<int>(keys_.size());
  // A repeated key is found at its first position, so a hint at a later one must not answer:
  // each position is marked by whether an earlier one in its bucket has its key.
  reserve_growing(first_, keys_.size());
  first_.assign(keys_.size(), 1);
  for (std::size_t b = 0; b < buckets; ++b)
    for (int e = bucket_start_[b] + 1; e < bucket_start_[b + 1]; ++e)
      for (int earlier = bucket_start_[b]; earlier < e; ++earlier)
        if (filed_key(earlier) == filed_key(e)) {
          first_[static_cast<std::size_t>(entries_[static_cast<std::size_t>(e)])] = 0;
          break;
        }
}

int ContactKeyIndex::find(const ContactKey& key, int hint) const {
  if (hint >= 0) {
    const std::size_t end = std::min(keys_.size(), static_cast<std::size_t>(hint) + kHintWindow);
    for (auto k = static_cast<std::size_t>(hint); k < end; ++k)
      if (keys_[k] == key) return first_[k] != 0 ? static_cast<int>(k) : find(key);
  }
  return find(key);
}

int ContactKeyIndex::find(const ContactKey& key) const {
  if (keys_.empty()) return -1;
  const std::size_t b = bucket_of(key);
  for (int e = bucket_start_[b]; e < bucket_start_[b + 1]; ++e) {
    const int k = entries_[static_cast<std::size_t>(e)];
    if (keys_[static_cast<std::size_t>(k)] == key) return k;
  }
  return -1;
}

}  // namespace impactbench::model
