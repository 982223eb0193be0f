#pragma once
// A map whose values are built once per key, by the first thread that asks; the others wait
// for that build and share its result (or its exception) read-only.
#include <cstddef>
#include <future>
#include <map>
#include <memory>
#include <mutex>

namespace grpvss::batch {

template <class Key, class Value>
class OnceCache {
 public:
  using Pointer = std::shared_ptr<const Value>;

  /// The value for `key`, built by `build()` (returning a Pointer) on the first request,
  /// outside the lock; a build's exception is rethrown to every request for the key.
  template <class Build>
  Pointer get(const Key& key, Build&& build) {
    std::promise<Pointer> promise;
    std::shared_future<Pointer> future;
    bool mine = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto found = entries_.find(key);
      if (found != entries_.end()) {
        future = found->second;
      } else {
        future = promise.get_future().share();
        entries_.emplace(key, future);
        ++builds_;
        mine = true;
      }
    }
    if (mine) {
      try {
        promise.set_value(build());
      } catch (...) {
        promise.set_exception(std::current_exception());
      }
    }
    return future.get();
  }

  /// How many keys were built (or are being built).
  std::size_t builds() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return builds_;
  }

 private:
  mutable std::mutex mutex_;
  std::map<Key, std::shared_future<Pointer>> entries_;
  std::size_t builds_ = 0;
};

}  // namespace grpvss::batch
