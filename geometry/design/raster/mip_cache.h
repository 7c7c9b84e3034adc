// geometry/design/raster/mip_cache.h: the mip pyramids of the last few source images, so designs
// rendered one after another on the same renderer base (the studio's previews) build each once.
#pragma once

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>

#include "geometry/common/image.h"
#include "geometry/design/raster/mip_image.h"

namespace tp::geometry::internal {

/// A small least-recently-used cache of MipImages keyed by the source image (the same object,
/// still alive) and the wrap modes. The pyramid is the one MipImage builds, so a renderer made
/// with the cache renders the same pixels as one made without. Thread-safe.
class MipCache {
 public:
  explicit MipCache(std::size_t capacity = 6) : capacity_(capacity) {}

  /// The pyramid of `image` (non-empty) with these wraps: kept, or built and kept.
  [[nodiscard]] std::shared_ptr<const MipImage> get(const ImageHandle& image, Wrap wrap_u, Wrap wrap_v);

 private:
  struct Entry {
    std::weak_ptr<const ImageRgba8> source;  ///< expired: the address may have been reused
    const ImageRgba8* address = nullptr;
    Wrap wrap_u, wrap_v;
    std::shared_ptr<const MipImage> mip;
  };
  std::size_t capacity_;
  std::mutex mu_;
  std::list<Entry> entries_;  ///< most recently used first
};

/// `image`'s pyramid from `cache`, or a fresh one when there is no cache.
[[nodiscard]] std::shared_ptr<const MipImage> mip_of(const ImageHandle& image, Wrap wrap_u, Wrap wrap_v,
                                                     MipCache* cache);

}  // namespace tp::geometry::internal
