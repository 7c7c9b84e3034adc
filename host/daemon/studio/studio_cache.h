// host/daemon/studio/studio_cache.h: the daemon's studio garments, kept in memory by id with a
// bound on how many (least recently used goes first, its session folder with it).
#pragma once

#include <atomic>
#include <cstddef>
#include <filesystem>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "host/daemon/studio/studio_garment.h"

namespace tp::host {

class StudioCache {
 public:
  /// Session folders go under `root` (created on first use); `root`'s siblings named studio-*,
  /// earlier runs' sessions, are removed.
  StudioCache(std::filesystem::path root, std::size_t capacity);
  /// Drops every garment (cancelling their background sewings) and waits for those to end.
  ~StudioCache();
  StudioCache(const StudioCache&) = delete;
  StudioCache& operator=(const StudioCache&) = delete;

  /// A fresh unguessable id (16 hex digits) and its session folder, created with assets/.
  [[nodiscard]] Result<std::pair<std::string, std::filesystem::path>> new_session();
  /// Keeps `g`; evicts the least recently used garment beyond the capacity.
  void put(std::shared_ptr<StudioGarment> g);
  /// The garment `id` (marked as just used), or null.
  [[nodiscard]] std::shared_ptr<StudioGarment> get(const std::string& id);
  /// Forgets `id`; false when it was not there.
  bool erase(const std::string& id);
  [[nodiscard]] std::size_t size() const;
  [[nodiscard]] std::size_t capacity() const { return capacity_; }

  /// Garments being sewn at once (the routes refuse more than a few: sewing takes both cores).
  std::atomic<int> sewing{0};

 private:
  std::filesystem::path root_;
  std::size_t capacity_;
  mutable std::mutex mu_;
  std::list<std::shared_ptr<StudioGarment>> order_;  ///< most recently used first
  std::unordered_map<std::string, std::list<std::shared_ptr<StudioGarment>>::iterator> index_;
};

}  // namespace tp::host
