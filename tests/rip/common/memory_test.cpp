// tests/rip/common/memory_test.cpp: the huge-page memory block and the allocator policy.
#include "rip/common/memory.h"

#include <cstdint>
#include <cstring>

#include <gtest/gtest.h>

namespace tp::rip {
namespace {

TEST(HugePageBlock, MapsZeroedMemoryThatCanBeWrittenEverywhere) {
  HugePageBlock block;
  constexpr std::size_t kBytes = (std::size_t{5} << 20) + 123;  // not a whole number of huge pages
  ASSERT_TRUE(block.allocate(kBytes));
  ASSERT_NE(block.data(), nullptr);
  EXPECT_EQ(block.size_bytes(), kBytes);
  auto* bytes = static_cast<std::uint8_t*>(block.data());
  EXPECT_EQ(bytes[0], 0);
  EXPECT_EQ(bytes[kBytes - 1], 0);
  std::memset(bytes, 0xab, kBytes);
  EXPECT_EQ(bytes[kBytes / 2], 0xab);
}

TEST(HugePageBlock, AllocatingAgainReplacesTheBlockAndZeroBytesIsEmpty) {
  HugePageBlock block;
  ASSERT_TRUE(block.allocate(4096));
  static_cast<std::uint8_t*>(block.data())[0] = 7;
  ASSERT_TRUE(block.allocate(8192));
  EXPECT_EQ(block.size_bytes(), 8192u);
  EXPECT_EQ(static_cast<std::uint8_t*>(block.data())[0], 0);
  ASSERT_TRUE(block.allocate(0));
  EXPECT_EQ(block.data(), nullptr);
  EXPECT_EQ(block.size_bytes(), 0u);
}

TEST(AdviseHugePages, AcceptsRangesSmallerThanOneHugePage) {
  std::uint8_t small[100] = {};
  advise_huge_pages(small, sizeof small);  // nothing whole to advise: a no-op, not a crash
  advise_huge_pages(nullptr, 0);
  EXPECT_EQ(small[0], 0);
}

}  // namespace
}  // namespace tp::rip
