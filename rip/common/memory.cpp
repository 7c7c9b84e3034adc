// rip/common/memory.cpp: fixes glibc's mmap threshold (see memory.h).
#include "rip/common/memory.h"

#include <malloc.h>

namespace tp::rip {

bool keep_memory_flat() {
#if defined(__GLIBC__)
  return mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThresholdBytes)) == 1;
#else
  return true;
#endif
}

}  // namespace tp::rip
