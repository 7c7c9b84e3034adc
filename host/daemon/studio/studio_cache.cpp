// host/daemon/studio/studio_cache.cpp: the bounded LRU of studio garments.
#include "host/daemon/studio/studio_cache.h"

#include <malloc.h>

#include <random>

namespace tp::host {

namespace fs = std::filesystem;

StudioCache::StudioCache(fs::path root, std::size_t capacity)
    : root_(std::move(root)), capacity_(std::max<std::size_t>(1, capacity)) {
  // Every preview builds and frees tens of MiB of render triangles and images. With glibc's
  // 128 KiB trim threshold the freed heap goes back to the system after each one and the kernel
  // zeroes every page again for the next (measured: half of a preview's CPU time under load).
  // Keeping up to 256 MiB of freed heap lets the next preview reuse it; blocks above printd's
  // mmap threshold (rip/common/memory.h) are still mapped and returned, so RIP memory stays flat.
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  // Sessions of an earlier printd on this state directory (stopped, or killed) are gone with it.
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(root_.parent_path(), ec))
    if (e.is_directory() && e.path().filename().string().rfind("studio-", 0) == 0) fs::remove_all(e.path(), ec);
  fs::remove_all(root_, ec);
}

StudioCache::~StudioCache() {
  {
    std::lock_guard lock(mu_);
    index_.clear();
    order_.clear();
  }
  wait_for_print_sewings();
}

Result<std::pair<std::string, fs::path>> StudioCache::new_session() {
  static std::mutex rng_mu;
  static std::random_device rd;
  std::string id;
  {
    std::lock_guard lock(rng_mu);
    const std::uint64_t v = (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
    static const char* hex = "0123456789abcdef";
    for (int i = 15; i >= 0; --i) id += hex[(v >> (4 * i)) & 15];
  }
  const fs::path dir = root_ / id;
  std::error_code ec;
  fs::create_directories(dir / "assets", ec);
  if (ec) return fail(ErrorCode::kIo, (dir / "assets").string() + ": " + ec.message());
  return std::pair{id, dir};
}

void StudioCache::put(std::shared_ptr<StudioGarment> g) {
  std::lock_guard lock(mu_);
  if (auto it = index_.find(g->id); it != index_.end()) {
    order_.erase(it->second);
    index_.erase(it);
  }
  order_.push_front(g);
  index_[g->id] = order_.begin();
  while (order_.size() > capacity_) {
    index_.erase(order_.back()->id);
    order_.pop_back();
  }
}

std::shared_ptr<StudioGarment> StudioCache::get(const std::string& id) {
  std::lock_guard lock(mu_);
  auto it = index_.find(id);
  if (it == index_.end()) return nullptr;
  order_.splice(order_.begin(), order_, it->second);
  return *order_.begin();
}

bool StudioCache::erase(const std::string& id) {
  std::lock_guard lock(mu_);
  auto it = index_.find(id);
  if (it == index_.end()) return false;
  order_.erase(it->second);
  index_.erase(it);
  return true;
}

std::size_t StudioCache::size() const {
  std::lock_guard lock(mu_);
  return order_.size();
}

}  // namespace tp::host
