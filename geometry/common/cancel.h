// geometry/common/cancel.h: a cancellation token passed down the pipeline and checked between bands.
#pragma once

#include <atomic>
#include <memory>

namespace tp::geometry {

/// Shared flag: the host sets it, long-running stages poll it between units of work.
class CancelToken {
 public:
  CancelToken() : flag_(std::make_shared<std::atomic<bool>>(false)) {}
  void cancel() const { flag_->store(true, std::memory_order_relaxed); }
  [[nodiscard]] bool cancelled() const { return flag_->load(std::memory_order_relaxed); }

 private:
  std::shared_ptr<std::atomic<bool>> flag_;
};

}  // namespace tp::geometry
