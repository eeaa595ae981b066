// The embedded shader tables that ffx-dof-shaderc generates, and how to look a permutation up.
//
// One PassTable per pass and language. A permutation is one value per axis; its index is mixed
// radix over the axes in table order, the last axis varying fastest:
//   index = sum_i valueIndex_i * prod_{j > i} axes[j].valueCount
// Several permutations may share one blob (identical binaries are stored once), so
// permutationToBlob maps every index to a blob. A key that is not in the table is an error, never
// a silent fallback to permutation 0.
//
// The generated library of a target (cmake: ffx_dof_add_shader_library) also provides
// <target>.h with findPassTable(pass) in the namespace chosen there (default
// ffxdof::shaders::<language>).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ffxdof::shaders {

enum class BindingKind : uint32_t {
    SampledImage,   // texture2D / Texture2D (read through a separate sampler or texelFetch)
    StorageImage,   // image2D / RWTexture2D
    StorageBuffer,  // buffer block / RWStructuredBuffer / RWByteAddressBuffer
    Sampler,        // sampler / SamplerState
    UniformBuffer,  // uniform block / cbuffer (ffx-dof itself uses push constants instead)
    PushConstants,  // push_constant block / [[vk::push_constant]]; set and binding are 0
};

// One resource the pass's shaders declare. For PushConstants, `size` is the block size in bytes;
// for every other kind it is 0. Names are the shader-side variable names.
struct Binding {
    const char* name;
    uint32_t set;
    uint32_t binding;
    BindingKind kind;
    uint32_t arraySize;  // 1 for a single resource
    uint32_t size;
};

// Byte offset of one member of the push-constant block (reflected), for layout checks.
struct PushConstantMember {
    const char* name;
    uint32_t offset;
    uint32_t size;
};

// What a blob needs of the device beyond core Vulkan: one bit per SPIR-V capability that a Vulkan
// device only accepts with an optional feature enabled (or, for the GroupNonUniform* ones, with a
// subgroup operation the device reports). ffx-dof-shaderc reflects them from the declared
// capabilities of each binary and refuses a capability it cannot classify, so this list covers
// every blob. The bit is named after the capability; the Vulkan feature is in the comment.
enum class Feature : uint32_t {
    Float16 = 1u << 0,                             // shaderFloat16
    Float64 = 1u << 1,                             // shaderFloat64
    Int8 = 1u << 2,                                // shaderInt8
    Int16 = 1u << 3,                               // shaderInt16
    Int64 = 1u << 4,                               // shaderInt64
    StorageBuffer16BitAccess = 1u << 5,            // storageBuffer16BitAccess
    UniformAndStorageBuffer16BitAccess = 1u << 6,  // uniformAndStorageBuffer16BitAccess
    StoragePushConstant16 = 1u << 7,               // storagePushConstant16
    StorageBuffer8BitAccess = 1u << 8,             // storageBuffer8BitAccess
    UniformAndStorageBuffer8BitAccess = 1u << 9,   // uniformAndStorageBuffer8BitAccess
    StoragePushConstant8 = 1u << 10,               // storagePushConstant8
    StorageImageReadWithoutFormat = 1u << 11,      // shaderStorageImageReadWithoutFormat
    StorageImageWriteWithoutFormat = 1u << 12,     // shaderStorageImageWriteWithoutFormat
    ImageGatherExtended = 1u << 13,                // shaderImageGatherExtended
    VulkanMemoryModel = 1u << 14,                  // vulkanMemoryModel
    VulkanMemoryModelDeviceScope = 1u << 15,       // vulkanMemoryModelDeviceScope
    GroupNonUniform = 1u << 16,                    // subgroup operations: VK_SUBGROUP_FEATURE_BASIC_BIT
    GroupNonUniformVote = 1u << 17,                // VK_SUBGROUP_FEATURE_VOTE_BIT
    GroupNonUniformArithmetic = 1u << 18,          // VK_SUBGROUP_FEATURE_ARITHMETIC_BIT
    GroupNonUniformBallot = 1u << 19,              // VK_SUBGROUP_FEATURE_BALLOT_BIT
    GroupNonUniformShuffle = 1u << 20,             // VK_SUBGROUP_FEATURE_SHUFFLE_BIT
    GroupNonUniformShuffleRelative = 1u << 21,     // VK_SUBGROUP_FEATURE_SHUFFLE_RELATIVE_BIT
    GroupNonUniformClustered = 1u << 22,           // VK_SUBGROUP_FEATURE_CLUSTERED_BIT
    GroupNonUniformQuad = 1u << 23,                // VK_SUBGROUP_FEATURE_QUAD_BIT
};
constexpr uint32_t kFeatureCount = 24;
constexpr uint32_t featureBit(Feature feature) { return static_cast<uint32_t>(feature); }
// The capability's name ("Float16"); nullptr for a value that is not one bit of Feature.
const char* featureName(Feature feature);

// One unique binary: SPIR-V, or for language "dxil" the DXIL container (its bytes as words). localSize is the reflected
// workgroup size; it can differ between blobs of one pass (the wave64 axis changes it), so it lives here and not on the
// pass.
struct Blob {
    const uint32_t* words;
    size_t wordCount;
    uint32_t localSize[3];
    // Feature bits: the optional capabilities the SPIR-V declares (the FFX_HALF=1 permutations
    // declare Float16). For "dxil" tables, those of the SPIR-V compiled from the same permutation
    // for the reflection: Float16 there is the DXIL's native 16-bit types.
    uint32_t requiredFeatures;
};

struct Axis {
    const char* macro;
    const uint32_t* values;
    uint32_t valueCount;
};

struct PassTable {
    const char* pass;      // "blur"
    const char* language;  // "glsl" or "hlsl" (both compiled to SPIR-V), or "dxil" (HLSL by dxc)
    const Axis* axes;
    uint32_t axisCount;
    const Blob* blobs;  // unique binaries
    uint32_t blobCount;
    const uint16_t* permutationToBlob;
    uint32_t permutationCount;  // product of the axes' valueCount
    // Union over all permutations: a permutation may leave a resource unused (the optimizer
    // removes it), but no two permutations may give one name different slots or kinds.
    // DXIL: set = register space, binding = register number; the class (t, u, s, b) is the kind's.
    const Binding* bindings;
    uint32_t bindingCount;
    const PushConstantMember* pushConstantMembers;
    uint32_t pushConstantMemberCount;
};

using Define = std::pair<std::string, uint32_t>;

// Index of the permutation with exactly these macro values: every axis named once, no other
// macro, every value one of the axis's values. Returns false and sets *error (when not null) to
// a one-line reason otherwise.
bool findPermutationIndex(const PassTable& table, const std::vector<Define>& defines, uint32_t* index,
                          std::string* error);

// The blob of the permutation with exactly these macro values; nullptr and *error otherwise.
const Blob* findPermutation(const PassTable& table, const std::vector<Define>& defines, std::string* error);

// The macro values of permutation `index`, in axis order (the inverse of findPermutationIndex).
std::vector<Define> permutationDefines(const PassTable& table, uint32_t index);

// The table named `pass` among `tables`, or nullptr.
const PassTable* findPassTable(const PassTable* const* tables, size_t tableCount, const char* pass);

// The binding named `name` in the table, or nullptr.
const Binding* findBinding(const PassTable& table, const char* name);

const char* bindingKindName(BindingKind kind);

}  // namespace ffxdof::shaders
