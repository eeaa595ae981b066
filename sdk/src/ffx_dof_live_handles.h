// The registry of live handles, one per handle kind (contexts, backends). Private to ffx-dof.
//
// Public handles are raw pointers that an engine may keep after destroying them or may fill with
// garbage. Every entry point looks the pointer up here before it dereferences it, so a stale or
// garbage handle is an error code instead of a use-after-free or a crash.
#pragma once

#include <mutex>
#include <unordered_set>

namespace ffxdof {

template <typename Handle>
class LiveHandles {
public:
    void insert(const Handle* handle) {
        std::lock_guard<std::mutex> lock(mutex_);
        handles_.insert(handle);
    }
    // False when the handle was not live (destroyed twice, or never made).
    bool erase(const Handle* handle) {
        std::lock_guard<std::mutex> lock(mutex_);
        return handles_.erase(handle) != 0;
    }
    bool contains(const Handle* handle) const {
        std::lock_guard<std::mutex> lock(mutex_);
        return handles_.count(handle) != 0;
    }
    // Runs action() under the registry's lock when the handle is live and returns its result (a value
    // convertible to bool); returns notLive otherwise. Holding the lock lets a caller check a handle
    // and change it (or erase it) without another thread destroying it in between.
    template <typename Result, typename Action>
    Result whileLive(const Handle* handle, Result notLive, Action action) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (handles_.count(handle) == 0) return notLive;
        return action([&] { handles_.erase(handle); });
    }

private:
    mutable std::mutex mutex_;
    std::unordered_set<const Handle*> handles_;
};

}  // namespace ffxdof
