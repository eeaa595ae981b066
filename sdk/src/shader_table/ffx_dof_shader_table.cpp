#include "ffx_dof_shader_table.h"

#include <cstring>

namespace ffxdof::shaders {
namespace {

void setError(std::string* error, std::string message) {
    if (error) *error = std::move(message);
}

}  // namespace

bool findPermutationIndex(const PassTable& table, const std::vector<Define>& defines, uint32_t* index,
                          std::string* error) {
    for (const Define& define : defines) {
        bool known = false;
        for (uint32_t a = 0; a < table.axisCount; ++a) known = known || define.first == table.axes[a].macro;
        if (!known) {
            setError(error, "pass '" + std::string(table.pass) + "' (" + table.language + ") has no axis '" +
                                define.first + "'");
            return false;
        }
    }
    uint32_t result = 0;
    for (uint32_t a = 0; a < table.axisCount; ++a) {
        const Axis& axis = table.axes[a];
        const Define* found = nullptr;
        for (const Define& define : defines) {
            if (define.first != axis.macro) continue;
            if (found) {
                setError(error, std::string("axis '") + axis.macro + "' is given twice");
                return false;
            }
            found = &define;
        }
        if (!found) {
            setError(error, "pass '" + std::string(table.pass) + "' needs a value for axis '" + axis.macro + "'");
            return false;
        }
        uint32_t valueIndex = axis.valueCount;
        for (uint32_t v = 0; v < axis.valueCount; ++v) {
            if (axis.values[v] == found->second) valueIndex = v;
        }
        if (valueIndex == axis.valueCount) {
            std::string allowed;
            for (uint32_t v = 0; v < axis.valueCount; ++v) {
                allowed += (v ? "," : "") + std::to_string(axis.values[v]);
            }
            setError(error, std::string("axis '") + axis.macro + "' has no value " + std::to_string(found->second) +
                                " (allowed: {" + allowed + "})");
            return false;
        }
        result = result * axis.valueCount + valueIndex;
    }
    if (result >= table.permutationCount) {
        // Only a corrupt table gets here: the generator writes permutationCount = product of axes.
        setError(error, "permutation table of pass '" + std::string(table.pass) + "' is inconsistent");
        return false;
    }
    *index = result;
    return true;
}

const Blob* findPermutation(const PassTable& table, const std::vector<Define>& defines, std::string* error) {
    uint32_t index = 0;
    if (!findPermutationIndex(table, defines, &index, error)) return nullptr;
    const uint16_t blob = table.permutationToBlob[index];
    if (blob >= table.blobCount) {
        setError(error, "permutation table of pass '" + std::string(table.pass) + "' is inconsistent");
        return nullptr;
    }
    return &table.blobs[blob];
}

std::vector<Define> permutationDefines(const PassTable& table, uint32_t index) {
    std::vector<Define> defines(table.axisCount);
    for (uint32_t a = table.axisCount; a-- > 0;) {
        const Axis& axis = table.axes[a];
        defines[a] = {axis.macro, axis.values[index % axis.valueCount]};
        index /= axis.valueCount;
    }
    return defines;
}

const PassTable* findPassTable(const PassTable* const* tables, size_t tableCount, const char* pass) {
    if (!pass) return nullptr;
    for (size_t i = 0; i < tableCount; ++i) {
        if (std::strcmp(tables[i]->pass, pass) == 0) return tables[i];
    }
    return nullptr;
}

const Binding* findBinding(const PassTable& table, const char* name) {
    if (!name) return nullptr;
    for (uint32_t i = 0; i < table.bindingCount; ++i) {
        if (std::strcmp(table.bindings[i].name, name) == 0) return &table.bindings[i];
    }
    return nullptr;
}

const char* bindingKindName(BindingKind kind) {
    switch (kind) {
        case BindingKind::SampledImage:
            return "sampled_image";
        case BindingKind::StorageImage:
            return "storage_image";
        case BindingKind::StorageBuffer:
            return "storage_buffer";
        case BindingKind::Sampler:
            return "sampler";
        case BindingKind::UniformBuffer:
            return "uniform_buffer";
        case BindingKind::PushConstants:
            return "push_constants";
    }
    return "unknown";
}

const char* featureName(Feature feature) {
    switch (feature) {
        case Feature::Float16:
            return "Float16";
        case Feature::Float64:
            return "Float64";
        case Feature::Int8:
            return "Int8";
        case Feature::Int16:
            return "Int16";
        case Feature::Int64:
            return "Int64";
        case Feature::StorageBuffer16BitAccess:
            return "StorageBuffer16BitAccess";
        case Feature::UniformAndStorageBuffer16BitAccess:
            return "UniformAndStorageBuffer16BitAccess";
        case Feature::StoragePushConstant16:
            return "StoragePushConstant16";
        case Feature::StorageBuffer8BitAccess:
            return "StorageBuffer8BitAccess";
        case Feature::UniformAndStorageBuffer8BitAccess:
            return "UniformAndStorageBuffer8BitAccess";
        case Feature::StoragePushConstant8:
            return "StoragePushConstant8";
        case Feature::StorageImageReadWithoutFormat:
            return "StorageImageReadWithoutFormat";
        case Feature::StorageImageWriteWithoutFormat:
            return "StorageImageWriteWithoutFormat";
        case Feature::ImageGatherExtended:
            return "ImageGatherExtended";
        case Feature::VulkanMemoryModel:
            return "VulkanMemoryModel";
        case Feature::VulkanMemoryModelDeviceScope:
            return "VulkanMemoryModelDeviceScope";
        case Feature::GroupNonUniform:
            return "GroupNonUniform";
        case Feature::GroupNonUniformVote:
            return "GroupNonUniformVote";
        case Feature::GroupNonUniformArithmetic:
            return "GroupNonUniformArithmetic";
        case Feature::GroupNonUniformBallot:
            return "GroupNonUniformBallot";
        case Feature::GroupNonUniformShuffle:
            return "GroupNonUniformShuffle";
        case Feature::GroupNonUniformShuffleRelative:
            return "GroupNonUniformShuffleRelative";
        case Feature::GroupNonUniformClustered:
            return "GroupNonUniformClustered";
        case Feature::GroupNonUniformQuad:
            return "GroupNonUniformQuad";
    }
    return nullptr;
}

}  // namespace ffxdof::shaders
