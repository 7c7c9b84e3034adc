// rip/common/memory.h: the allocator policy of a process that RIPs rolls of any length.
#pragma once

#include <cstddef>

namespace tp::rip {

/// Largest block served from the heap once keep_memory_flat() has run; larger blocks are mapped
/// and returned to the system when freed.
inline constexpr std::size_t kMmapThresholdBytes = std::size_t{8} << 20;

/// The RIP allocates band and swath buffers of a few MB and frees them again, band after band.
/// glibc raises its mmap threshold to the largest block freed, after which such buffers come from
/// the heap arenas, whose fragmentation made peak memory grow with roll length (about 10 % from
/// 1 m to 20 m). Fixing the threshold keeps peak memory flat. At 1 MiB the renderer's per-call
/// row buffers were mapped and unmapped each time (9 % slower); 8 MiB keeps those on the heap and
/// maps only band-sized buffers. Call once at process start, before threads are started.
/// Returns false if the C library refused.
bool keep_memory_flat();

}  // namespace tp::rip
