// Binding reflection with the SPIRV-Cross C API (Debian's libspirv-cross-c-shared): it already
// resolves names, descriptor decorations, array sizes and the declared struct layout, which a
// hand-written decoration walk would have to reimplement; glslang's TProgram reflection would
// see the pre-optimization module, not the binary the backends bind.
#include "shaderc.h"

#include <spirv_cross_c.h>

#include <algorithm>
#include <memory>
#include <tuple>

namespace ffxdof::shaderc {
namespace {

struct ContextDeleter {
    void operator()(spvc_context context) const { spvc_context_destroy(context); }
};

void check(spvc_result result, spvc_context context, const char* what) {
    if (result != SPVC_SUCCESS) {
        throw Error(std::string("SPIR-V reflection failed (") + what +
                    "): " + spvc_context_get_last_error_string(context));
    }
}

uint32_t arraySizeOf(spvc_compiler compiler, spvc_type_id typeId, const std::string& name) {
    const spvc_type type = spvc_compiler_get_type_handle(compiler, typeId);
    const unsigned dimensions = spvc_type_get_num_array_dimensions(type);
    if (dimensions == 0) return 1;
    if (dimensions > 1 || !spvc_type_array_dimension_is_literal(type, 0) ||
        spvc_type_get_array_dimension(type, 0) == 0) {
        throw Error("resource '" + name + "': only one-dimensional arrays of literal size can be reflected");
    }
    return spvc_type_get_array_dimension(type, 0);
}

// A variable without a name (a GLSL block without instance name) is called by its type's name.
std::string resourceName(spvc_compiler compiler, const spvc_reflected_resource& resource) {
    if (resource.name && resource.name[0]) return resource.name;
    const char* typeName = spvc_compiler_get_name(compiler, resource.base_type_id);
    return typeName ? typeName : "";
}

// The push-constant block's scalars and vectors with their absolute offsets; members of nested
// structs are named "outer.inner", so a block that wraps FfxDofConstants in one member still
// lists every FfxDofConstants field.
void appendLeafMembers(spvc_compiler compiler, spvc_context context, spvc_type_id structId, const std::string& prefix,
                       uint32_t baseOffset, std::vector<ReflectedMember>* members) {
    const spvc_type type = spvc_compiler_get_type_handle(compiler, structId);
    const unsigned count = spvc_type_get_num_member_types(type);
    for (unsigned m = 0; m < count; ++m) {
        unsigned offset = 0;
        size_t size = 0;
        check(spvc_compiler_type_struct_member_offset(compiler, type, m, &offset), context, "member offset");
        check(spvc_compiler_get_declared_struct_member_size(compiler, type, m, &size), context, "member size");
        const std::string name = prefix + spvc_compiler_get_member_name(compiler, structId, m);
        const spvc_type_id memberId = spvc_type_get_member_type(type, m);
        const spvc_type member = spvc_compiler_get_type_handle(compiler, memberId);
        if (spvc_type_get_basetype(member) == SPVC_BASETYPE_STRUCT && spvc_type_get_num_array_dimensions(member) == 0) {
            appendLeafMembers(compiler, context, memberId, name + ".", baseOffset + offset, members);
        } else {
            members->push_back({name, baseOffset + offset, static_cast<uint32_t>(size)});
        }
    }
}

}  // namespace

bool ReflectedBinding::operator==(const ReflectedBinding& other) const {
    return std::tie(name, set, binding, kind, arraySize, size) ==
           std::tie(other.name, other.set, other.binding, other.kind, other.arraySize, other.size);
}

Reflection reflect(const std::vector<uint32_t>& spirv) {
    spvc_context rawContext = nullptr;
    if (spvc_context_create(&rawContext) != SPVC_SUCCESS) throw Error("SPIR-V reflection: out of memory");
    std::unique_ptr<spvc_context_s, ContextDeleter> context(rawContext);

    spvc_parsed_ir ir = nullptr;
    check(spvc_context_parse_spirv(rawContext, spirv.data(), spirv.size(), &ir), rawContext, "parse");
    spvc_compiler compiler = nullptr;
    check(spvc_context_create_compiler(rawContext, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler),
          rawContext, "compiler");
    spvc_resources resources = nullptr;
    check(spvc_compiler_create_shader_resources(compiler, &resources), rawContext, "resources");

    Reflection reflection;
    const std::pair<spvc_resource_type, BindingKind> kinds[] = {
        {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, BindingKind::SampledImage},
        {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, BindingKind::StorageImage},
        {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, BindingKind::StorageBuffer},
        {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, BindingKind::Sampler},
        {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, BindingKind::UniformBuffer},
    };
    for (const auto& [type, kind] : kinds) {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        check(spvc_resources_get_resource_list_for_type(resources, type, &list, &count), rawContext, "list");
        for (size_t i = 0; i < count; ++i) {
            ReflectedBinding binding;
            binding.name = resourceName(compiler, list[i]);
            binding.kind = kind;
            binding.set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
            binding.binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
            binding.arraySize = arraySizeOf(compiler, list[i].type_id, binding.name);
            if (kind == BindingKind::SampledImage || kind == BindingKind::StorageImage) {
                const spvc_type image = spvc_compiler_get_type_handle(compiler, list[i].base_type_id);
                if (spvc_type_get_image_dimension(image) == SpvDimBuffer) {
                    throw Error("resource '" + binding.name + "': texel buffers have no binding kind; use a buffer");
                }
            }
            reflection.bindings.push_back(binding);
        }
    }
    const spvc_resource_type unsupported[] = {
        SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE, SPVC_RESOURCE_TYPE_SUBPASS_INPUT};
    for (spvc_resource_type type : unsupported) {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        check(spvc_resources_get_resource_list_for_type(resources, type, &list, &count), rawContext, "list");
        if (count > 0) {
            throw Error("resource '" + std::string(list[0].name) +
                        "' has an unsupported kind (combined image samplers: use a texture and a sampler)");
        }
    }

    const spvc_reflected_resource* pushConstants = nullptr;
    size_t pushConstantCount = 0;
    check(spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, &pushConstants,
                                                    &pushConstantCount),
          rawContext, "push constants");
    for (size_t i = 0; i < pushConstantCount; ++i) {
        const spvc_type block = spvc_compiler_get_type_handle(compiler, pushConstants[i].base_type_id);
        size_t size = 0;
        check(spvc_compiler_get_declared_struct_size(compiler, block, &size), rawContext, "push constant size");
        ReflectedBinding binding;
        binding.name = resourceName(compiler, pushConstants[i]);
        binding.kind = BindingKind::PushConstants;
        binding.size = static_cast<uint32_t>(size);
        reflection.bindings.push_back(binding);
        appendLeafMembers(compiler, rawContext, pushConstants[i].base_type_id, "", 0, &reflection.pushConstantMembers);
    }
    std::sort(reflection.bindings.begin(), reflection.bindings.end(), [](const auto& a, const auto& b) {
        return std::make_tuple(a.kind == BindingKind::PushConstants, a.set, a.binding, a.name) <
               std::make_tuple(b.kind == BindingKind::PushConstants, b.set, b.binding, b.name);
    });

    for (unsigned axis = 0; axis < 3; ++axis) {
        reflection.localSize[axis] =
            spvc_compiler_get_execution_mode_argument_by_index(compiler, SpvExecutionModeLocalSize, axis);
    }
    const SpvCapability* capabilities = nullptr;
    size_t capabilityCount = 0;
    check(spvc_compiler_get_declared_capabilities(compiler, &capabilities, &capabilityCount), rawContext,
          "capabilities");
    reflection.requiredFeatures = requiredFeatures(std::vector<uint32_t>(capabilities, capabilities + capabilityCount));
    return reflection;
}

}  // namespace ffxdof::shaderc
