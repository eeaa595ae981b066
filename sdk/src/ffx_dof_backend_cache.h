// The objects a backend keeps for every context it makes (pipelines, their layouts), looked up by what
// they depend on. Compiling the pipelines is most of ffxDofContextCreate's cost (0.47 of 0.5 s on
// lavapipe at 160 x 128, about 13 pipelines), so a context made again with a backend, at a new
// resolution after a resize or with flags an earlier context had, compiles nothing. The objects live
// until the backend is destroyed; at most one per permutation a context has used. Private to ffx-dof.
#pragma once

#include "ffx_dof.h"

#include <cstddef>
#include <mutex>
#include <utility>
#include <vector>

namespace ffxdof {

// Key: equality-comparable; Object: a handle (copied out). Thread-safe: contexts of one backend may be
// made on several threads (one makes an object, the others wait for it).
template <typename Key, typename Object>
class BackendObjectCache {
public:
    // The object for key, made by create(Object*) -> FfxDofErrorCode the first time it is asked for. On
    // failure create's code is returned and nothing is kept.
    template <typename Create>
    FfxDofErrorCode findOrCreate(const Key& key, Object* out, Create&& create) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const std::pair<Key, Object>& entry : entries_) {
            if (entry.first == key) {
                *out = entry.second;
                return FFX_DOF_OK;
            }
        }
        entries_.reserve(entries_.size() + 1);  // may throw before anything is made, never after
        Object made{};
        const FfxDofErrorCode status = create(&made);
        if (status != FFX_DOF_OK) return status;
        entries_.emplace_back(key, made);
        *out = made;
        return FFX_DOF_OK;
    }

    // Hands every object to destroy(Object&) and forgets them (the backend's destructor).
    template <typename Destroy>
    void clear(Destroy&& destroy) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (std::pair<Key, Object>& entry : entries_) destroy(entry.second);
        entries_.clear();
    }

    size_t size() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return entries_.size();
    }

private:
    mutable std::mutex mutex_;
    std::vector<std::pair<Key, Object>> entries_;
};

}  // namespace ffxdof
