// Huge-page helpers for large vectors (engine/core/memory.hpp): advice only, so the vector must
// behave exactly as reserve()/resize() would.
#include "engine/core/memory.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace lunaster::engine {
namespace {

constexpr std::size_t kLarge = std::size_t{3} << 20;  // ints: 12 MB, several huge pages

TEST(HugePages, ReserveKeepsTheValuesAndTheBlockWhenThereIsRoom) {
  std::vector<int> v = {7, 8, 9};
  reserve_on_huge_pages(v, kLarge);
  ASSERT_GE(v.capacity(), kLarge);
  EXPECT_EQ(v, (std::vector<int>{7, 8, 9}));
  const int* block = v.data();
  reserve_on_huge_pages(v, kLarge / 2);  // enough room already: no new block
  EXPECT_EQ(v.data(), block);
  for (std::size_t i = 3; i < kLarge; ++i) v.push_back(static_cast<int>(i));
  EXPECT_EQ(v.data(), block);  // the reserved room was used, not reallocated
  EXPECT_EQ(v[kLarge - 1], static_cast<int>(kLarge - 1));
}

TEST(HugePages, ResizeKeepsTheValuesAndZeroesTheRest) {
  std::vector<double> v = {1.5, -2.0};
  resize_on_huge_pages(v, kLarge);
  ASSERT_EQ(v.size(), kLarge);
  EXPECT_EQ(v[0], 1.5);
  EXPECT_EQ(v[1], -2.0);
  std::size_t nonzero = 0;
  for (std::size_t i = 2; i < v.size(); ++i) nonzero += v[i] != 0.0;
  EXPECT_EQ(nonzero, 0U);
  resize_on_huge_pages(v, 1);  // shrinking is resize()'s
  EXPECT_EQ(v, (std::vector<double>{1.5}));
}

}  // namespace
}  // namespace lunaster::engine
