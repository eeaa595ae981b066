// The D3D12 resource states of one dispatch: which subresources each pass reads and writes (the
// plan's reflected slots), and the transitions and UAV barriers that make each pass's accesses legal.
#pragma once

#include "ffx_dof_dx12_backend.h"

#include <cstdint>

namespace ffxdof::dx12 {

constexpr D3D12_RESOURCE_STATES kReadState = D3D12_RESOURCE_STATE_NON_PIXEL_SHADER_RESOURCE;
constexpr D3D12_RESOURCE_STATES kWriteState = D3D12_RESOURCE_STATE_UNORDERED_ACCESS;

constexpr D3D12_RESOURCE_STATES kIndirectState = D3D12_RESOURCE_STATE_INDIRECT_ARGUMENT;

// Subresources whose states a dispatch follows: every level of every internal image, TILE_LIST_ARGS
// (a UAV for the passes that write it, indirect arguments for the composite), plus color, depth and
// output (whole resources; output shares color's entry when in place). GLOBALS, TILE_LISTS and HIGHLIGHTS
// stay UAVs and need only UAV barriers.
constexpr uint32_t kMaxTracked = kInternalImageCount * kMipCount + 4;
constexpr uint8_t kNoTarget = 0xff;

// Which tracked entries each binding slot reaches in one dispatch.
struct SlotTargets {
    struct Range {
        uint8_t first = kNoTarget;
        uint8_t count = 0;
    };
    Range srv[kSrvCount];
    uint8_t uavImage[kUavImageCount];
    uint8_t uavBuffer[kUavBufferCount];  // kNoTarget: a buffer that stays a UAV (UAV barriers only)
    uint8_t indirectArgs = kNoTarget;    // TILE_LIST_ARGS, where a pass reads its dispatch arguments
    SlotTargets() {
        for (uint8_t& target : uavImage) target = kNoTarget;
        for (uint8_t& target : uavBuffer) target = kNoTarget;
    }
};

enum class Access : uint8_t { None, Read, Write, Indirect };

// Follows the state of every tracked subresource through the passes and batches the barriers that
// make each pass's accesses legal. Without a command list it only simulates (to find rest states).
class StateTracker {
public:
    struct Entry {
        ID3D12Resource* resource = nullptr;
        UINT subresource = D3D12_RESOURCE_BARRIER_ALL_SUBRESOURCES;
        D3D12_RESOURCE_STATES state = D3D12_RESOURCE_STATE_COMMON;
        D3D12_RESOURCE_STATES final = D3D12_RESOURCE_STATE_COMMON;
        bool unorderedWrites = false;  // written through a UAV with no barrier since
    };

    uint8_t track(ID3D12Resource* resource, UINT subresource, D3D12_RESOURCE_STATES state,
                  D3D12_RESOURCE_STATES final) {
        Entry& entry = entries_[count_];
        entry.resource = resource;
        entry.subresource = subresource;
        entry.state = state;
        entry.final = final;
        // Writes before this dispatch (the engine's, or a previous dispatch's) may still be in flight.
        entry.unorderedWrites = state == kWriteState;
        return static_cast<uint8_t>(count_++);
    }

    // The pass's accesses are its reflected slots (the plan's); a storage slot is a write. `uavBuffers`:
    // the buffers by slot (those without a tracked entry stay UAVs).
    void beforePass(const SlotTargets& slots, const PlannedPass& pass, ID3D12Resource* const* uavBuffers) {
        for (uint32_t i = 0; i < count_; ++i) access_[i] = Access::None;
        for (uint32_t slot = 0; slot < kSrvCount; ++slot) {
            if (!(pass.sampledSlots & (1u << slot))) continue;
            for (uint32_t i = 0; i < slots.srv[slot].count; ++i) access_[slots.srv[slot].first + i] = Access::Read;
        }
        // A write wins over a read of the same subresource: in place, the composite pass binds the
        // color and the output, and its OUTPUT_PRE_INIT permutation reads the color through the output.
        for (uint32_t slot = 0; slot < kUavImageCount; ++slot) {
            if ((pass.storageSlots & (1u << slot)) && slots.uavImage[slot] != kNoTarget)
                access_[slots.uavImage[slot]] = Access::Write;
        }
        for (uint32_t slot = 0; slot < kUavBufferCount; ++slot) {
            if ((pass.bufferSlots & (1u << slot)) && slots.uavBuffer[slot] != kNoTarget)
                access_[slots.uavBuffer[slot]] = Access::Write;
        }
        if (pass.indirect != 0 && slots.indirectArgs != kNoTarget) access_[slots.indirectArgs] = Access::Indirect;
        for (uint32_t i = 0; i < count_; ++i) {
            Entry& entry = entries_[i];
            if (access_[i] == Access::Indirect && entry.state != kIndirectState) {
                transition(entry, kIndirectState);
            } else if (access_[i] == Access::Read && (entry.state & kReadState) == 0) {
                transition(entry, kReadState);
            } else if (access_[i] == Access::Write && entry.state != kWriteState) {
                transition(entry, kWriteState);
            } else if (access_[i] == Access::Write && entry.unorderedWrites) {
                uavBarrier(entry.resource);
            }
            if (access_[i] != Access::None) entry.unorderedWrites = false;
        }
        // GLOBALS, TILE_LISTS and HIGHLIGHTS stay UAVs (buffers: promoted from COMMON on first use, decay
        // after the list), so only UAV barriers order one pass's accesses against the next's.
        for (uint32_t slot = 0; slot < kUavBufferCount; ++slot) {
            if ((pass.bufferSlots & (1u << slot)) && slots.uavBuffer[slot] == kNoTarget && bufferWritten_[slot])
                uavBarrier(uavBuffers != nullptr ? uavBuffers[slot] : nullptr);
        }
    }

    void afterPass(const PlannedPass& pass) {
        for (uint32_t i = 0; i < count_; ++i) {
            if (access_[i] == Access::Write) entries_[i].unorderedWrites = true;
        }
        for (uint32_t slot = 0; slot < kUavBufferCount; ++slot)
            bufferWritten_[slot] = bufferWritten_[slot] || (pass.bufferSlots & (1u << slot)) != 0;
    }

    // Back to the states the engine declared (engine images) and the rest states (internal images).
    void restore() {
        for (uint32_t i = 0; i < count_; ++i) {
            Entry& entry = entries_[i];
            if (entry.state != entry.final) {
                transition(entry, entry.final);
            } else if (entry.state == kWriteState && entry.unorderedWrites) {
                uavBarrier(entry.resource);  // the engine's next UAV access must see our writes
            }
        }
    }

    // A dispatch may follow another in the same command list: its first accesses of the UAV buffers
    // (GLOBALS atomics, TILE_LISTS, HIGHLIGHTS) must wait for the previous dispatch's.
    void assumeBuffersWritten() {
        for (bool& written : bufferWritten_) written = true;
    }

    void flush(ID3D12GraphicsCommandList* list) {
        if (list != nullptr && barrierCount_ != 0) list->ResourceBarrier(barrierCount_, barriers_);
        barrierCount_ = 0;
    }

    const Entry& entry(uint32_t index) const { return entries_[index]; }

private:
    void transition(Entry& entry, D3D12_RESOURCE_STATES after) {
        D3D12_RESOURCE_BARRIER& barrier = barriers_[barrierCount_++];
        barrier = {};
        barrier.Type = D3D12_RESOURCE_BARRIER_TYPE_TRANSITION;
        barrier.Transition.pResource = entry.resource;
        barrier.Transition.Subresource = entry.subresource;
        barrier.Transition.StateBefore = entry.state;
        barrier.Transition.StateAfter = after;
        entry.state = after;
    }

    void uavBarrier(ID3D12Resource* resource) {
        for (UINT b = 0; b < barrierCount_; ++b) {
            if (barriers_[b].Type == D3D12_RESOURCE_BARRIER_TYPE_UAV && barriers_[b].UAV.pResource == resource) return;
        }
        D3D12_RESOURCE_BARRIER& barrier = barriers_[barrierCount_++];
        barrier = {};
        barrier.Type = D3D12_RESOURCE_BARRIER_TYPE_UAV;
        barrier.UAV.pResource = resource;
    }

    Entry entries_[kMaxTracked];
    Access access_[kMaxTracked]{};
    uint32_t count_ = 0;
    bool bufferWritten_[kUavBufferCount] = {};
    D3D12_RESOURCE_BARRIER barriers_[2 * kMaxTracked + 1]{};
    UINT barrierCount_ = 0;
};

}  // namespace ffxdof::dx12
