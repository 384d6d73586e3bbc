// The key index the time stepper uses for warm starts and late contacts: every filed key is
// found at its position (the first one when repeated), with or without a hint near a position,
// absent keys are not, against a linear search over random keys, and rebuilding forgets what was
// filed before.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "lib/model/contact_key_index.hpp"

namespace impactbench::model {
namespace {

int linear_find(const std::vector<ContactKey>& keys, const ContactKey& key) {
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (keys[k] == key) return static_cast<int>(k);
  return -1;
}

TEST(ContactKeyIndex, FindsWhatALinearSearchFinds) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> body(-1, 40);
  std::uniform_int_distribution<int> feature(0, 5);
  const auto random_key = [&] {
    return ContactKey{body(random) + 1, body(random), feature(random)};
  };
  ContactKeyIndex index;
  for (const int count : {0, 1, 2, 3, 17, 300, 1000}) {
    std::vector<ContactKey> keys;
    for (int k = 0; k < count; ++k) keys.push_back(random_key());  // repeats among 41·42·6
    index.build(keys);
    EXPECT_EQ(index.size(), keys.size());
    int found = 0;
    for (const ContactKey& key : keys) {
      EXPECT_EQ(index.find(key), linear_find(keys, key));
      found += index.contains(key) ? 1 : 0;
    }
    // Any hint, at the key's own position, a few before it (within the positions tried from
    // the hint on), at a repeat of it or elsewhere, gives the same.
    const int window = static_cast<int>(ContactKeyIndex::kHintWindow);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const int at = static_cast<int>(k);
      for (const int hint :
           {-1, 0, at, at + 1, at - 1, at - window + 1, at - window, at - window - 1, count})
        ASSERT_EQ(index.find(keys[k], hint), linear_find(keys, keys[k])) << k << " " << hint;
    }
    EXPECT_EQ(found, count);
    for (int probe = 0; probe < 2000; ++probe) {
      const ContactKey key = random_key();
      EXPECT_EQ(index.find(key), linear_find(keys, key));
    }
  }
  // Rebuilt empty, nothing is found.
  index.clear();
  EXPECT_FALSE(index.contains({0, -1, 0}));
  EXPECT_EQ(index.size(), 0u);
}

// A hint a few positions before a repeated key must not answer with the repeat: the answer is
// the key's first position, also when that lies before the hint.
TEST(ContactKeyIndex, AHintBeforeARepeatFindsTheFirst) {
  const std::vector<ContactKey> keys = {{1, -1, 0}, {2, -1, 0}, {3, -1, 0}, {1, -1, 0},
                                        {4, -1, 0}, {3, -1, 0}, {5, -1, 0}};
  ContactKeyIndex index;
  index.build(keys);
  for (int hint = 0; hint < static_cast<int>(keys.size()); ++hint) {
    EXPECT_EQ(index.find({1, -1, 0}, hint), 0) << hint;
    EXPECT_EQ(index.find({3, -1, 0}, hint), 2) << hint;
    EXPECT_EQ(index.find({5, -1, 0}, hint), 6) << hint;
    EXPECT_EQ(index.find({6, -1, 0}, hint), -1) << hint;
  }
}

TEST(ContactKeyIndex, FindsARepeatedKeyAtItsFirstPosition) {
  const std::vector<ContactKey> keys = {{0, -1, 2}, {4, 1, 0}, {0, -1, 2}};  // 2 repeats 0
  ContactKeyIndex index;
  index.build(keys);
  EXPECT_EQ(index.find({0, -1, 2}), 0);
  EXPECT_EQ(index.find({0, -1, 2}, 2), 0);  // the repeat's position is not the answer
  EXPECT_EQ(index.find({4, 1, 0}), 1);
  EXPECT_EQ(index.find({4, 1, 1}), -1);
  EXPECT_EQ(index.find({1, 4, 0}), -1);
}

}  // namespace
}  // namespace impactbench::model
