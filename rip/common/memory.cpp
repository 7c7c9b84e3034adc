// rip/common/memory.cpp: glibc's mmap threshold and huge-page memory (see memory.h).
#include "rip/common/memory.h"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>

namespace tp::rip {

bool keep_memory_flat() {
#if defined(__GLIBC__)
  return mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThresholdBytes)) == 1;
#else
  return true;
#endif
}

void advise_huge_pages(void* p, std::size_t bytes) {
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

HugePageBlock::~HugePageBlock() { release(); }

void HugePageBlock::release() {
  if (data_) munmap(data_, bytes_);
  data_ = nullptr;
  bytes_ = 0;
}

bool HugePageBlock::allocate(std::size_t bytes) {
  release();
  if (bytes == 0) return true;
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) return false;
  advise_huge_pages(p, bytes);
  data_ = p;
  bytes_ = bytes;
  return true;
}

}  // namespace tp::rip
