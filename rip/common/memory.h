// rip/common/memory.h: the allocator policy of a process that RIPs rolls of any length.
#pragma once

#include <cstddef>

namespace tp::rip {

/// Largest block served from the heap once keep_memory_flat() has run; larger blocks are mapped
/// and returned to the system when freed.
inline constexpr std::size_t kMmapThresholdBytes = std::size_t{16} << 20;

/// The RIP allocates band and swath buffers of a few MB and frees them again, band after band.
/// glibc raises its mmap threshold to the largest block freed, after which such buffers come from
/// the heap arenas, whose fragmentation made peak memory grow with roll length (about 10 % from
/// 1 m to 20 m). Fixing the threshold keeps peak memory flat. The value is a trade-off measured
/// with `printctl bench rip --rss-lengths 1,20` and `printctl bench link`: at 1 MiB the
/// renderer's row buffers were mapped and unmapped on every call (RIP 9 % slower); at 8 MiB the
/// ~10 MB swaths were, and the link fell from 153 to 70 MB/s; 16 MiB keeps both (RIP 554 m2/h,
/// link 129 MB/s) with peak memory 300.2 MB at 1 m and 300.5 MB at 20 m. Call once at process
/// start, before threads are started. Returns false if the C library refused.
bool keep_memory_flat();

/// Asks the kernel to back the whole 2 MiB pages inside [p, p + bytes) with huge pages when they
/// are first touched (advice only; ignored where transparent huge pages are off). For large
/// buffers filled once, such as a swath: on this machine's virtualised kernel a 4 KiB page fault
/// costs about 11 us, so filling a fresh 35 MB swath took 100 ms in page faults alone.
void advise_huge_pages(void* p, std::size_t bytes);

/// Anonymous memory of its own (mapped, not from the heap), advised for huge pages: for large
/// tables touched at random, such as the colour table's direct lookup. Zero-filled on first touch.
class HugePageBlock {
 public:
  HugePageBlock() = default;
  ~HugePageBlock();
  HugePageBlock(const HugePageBlock&) = delete;
  HugePageBlock& operator=(const HugePageBlock&) = delete;

  /// Maps `bytes` (replacing any earlier block); false if the system has no memory for it.
  [[nodiscard]] bool allocate(std::size_t bytes);
  void* data() const { return data_; }
  std::size_t size_bytes() const { return bytes_; }

 private:
  void release();

  void* data_ = nullptr;
  std::size_t bytes_ = 0;
};

}  // namespace tp::rip
