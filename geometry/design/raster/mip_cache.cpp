// geometry/design/raster/mip_cache.cpp: the least-recently-used cache of mip pyramids.
#include "geometry/design/raster/mip_cache.h"

namespace tp::geometry::internal {

std::shared_ptr<const MipImage> MipCache::get(const ImageHandle& image, Wrap wrap_u, Wrap wrap_v) {
  {
    std::lock_guard lock(mu_);
    for (auto it = entries_.begin(); it != entries_.end();) {
      if (it->source.expired()) {
        it = entries_.erase(it);
        continue;
      }
      if (it->address == image.get() && it->wrap_u == wrap_u && it->wrap_v == wrap_v) {
        entries_.splice(entries_.begin(), entries_, it);
        return entries_.front().mip;
      }
      ++it;
    }
  }
  // Built outside the lock: a large image takes a while, and two threads building the same one
  // only waste time (both pyramids are equal).
  auto mip = std::make_shared<const MipImage>(*image, wrap_u, wrap_v);
  std::lock_guard lock(mu_);
  entries_.push_front({image, image.get(), wrap_u, wrap_v, mip});
  while (entries_.size() > capacity_) entries_.pop_back();
  return mip;
}

std::shared_ptr<const MipImage> mip_of(const ImageHandle& image, Wrap wrap_u, Wrap wrap_v, MipCache* cache) {
  if (cache) return cache->get(image, wrap_u, wrap_v);
  return std::make_shared<const MipImage>(*image, wrap_u, wrap_v);
}

}  // namespace tp::geometry::internal
