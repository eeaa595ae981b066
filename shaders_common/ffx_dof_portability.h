// The vocabulary every ffx_dof_*.h header is written in, mapped to three languages. The includer
// selects one by defining exactly one of:
//   FFX_GLSL  GLSL 4.50 with the extensions FidelityFX DoF lists (compiled by glslang)
//   FFX_HLSL  HLSL SM 6.2 (SM 6.6 for wave64) with -enable-16bit-types (dxc, or glslang's HLSL front end)
//   FFX_CPU   C++17 through GLM, so that the pure functions and whole passes run in unit tests;
//             defined automatically when __cplusplus is defined and neither of the others is.
// FFX_HALF (0 or 1) selects 16-bit arithmetic where the algorithm uses the FfxDof* precision aliases.
// On the CPU every 16-bit type is a 32-bit float: the CPU mapping checks the algorithm, not rounding.
//
// Rules for shared code (they keep all three languages happy):
//   - literals as 1.0f / 1u; FfxDofFloat(x) around any value that must become 16-bit (GLSL does not
//     narrow implicitly);
//   - only .x/.y/.z/.w member access (GLM has no swizzle members), no vector comparison or select;
//   - no scalar-to-vector constructors (HLSL rejects float3(x)): use ffxDofBroadcast3 and friends;
//   - functions start with FFX_DOF_INLINE; out/inout parameters through FFX_DOF_OUT / FFX_DOF_INOUT.
#ifndef FFX_DOF_PORTABILITY_H
#define FFX_DOF_PORTABILITY_H

#if !defined(FFX_GLSL) && !defined(FFX_HLSL) && !defined(FFX_CPU) && defined(__cplusplus)
#define FFX_CPU 1
#endif
#if (defined(FFX_GLSL) && (defined(FFX_HLSL) || defined(FFX_CPU))) || (defined(FFX_HLSL) && defined(FFX_CPU)) || \
    !(defined(FFX_GLSL) || defined(FFX_HLSL) || defined(FFX_CPU))
#error "define exactly one of FFX_GLSL, FFX_HLSL, FFX_CPU before including ffx_dof_portability.h"
#endif

#ifndef FFX_HALF
#define FFX_HALF 0
#endif
#ifndef FFX_DOF_OPTION_WAVE64
#define FFX_DOF_OPTION_WAVE64 0
#endif

// The FidelityFX type names are declared once: an engine that already included FidelityFX's
// ffx_common_types.h (guard FFX_COMMON_TYPES_H) keeps its own identical definitions.
#if !defined(FFX_COMMON_TYPES_H) && !defined(FFX_DOF_FFX_TYPES_DECLARED)
#define FFX_DOF_FFX_TYPES_DECLARED 1
#define FFX_DOF_DECLARE_FFX_TYPES 1
#else
#define FFX_DOF_DECLARE_FFX_TYPES 0
#endif

//==================================================================================================
#if defined(FFX_GLSL)
//==================================================================================================
#extension GL_EXT_samplerless_texture_functions : require
#extension GL_EXT_control_flow_attributes : enable
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_vote : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_quad : require
#extension GL_KHR_shader_subgroup_shuffle : require
#if FFX_HALF
#extension GL_EXT_shader_16bit_storage : require
#extension GL_EXT_shader_explicit_arithmetic_types : require
#extension GL_EXT_shader_subgroup_extended_types_float16 : require
#endif

#if FFX_DOF_DECLARE_FFX_TYPES
#define FfxFloat32 float
#define FfxFloat32x2 vec2
#define FfxFloat32x3 vec3
#define FfxFloat32x4 vec4
#define FfxInt32 int
#define FfxInt32x2 ivec2
#define FfxInt32x3 ivec3
#define FfxInt32x4 ivec4
#define FfxUInt32 uint
#define FfxUInt32x2 uvec2
#define FfxUInt32x3 uvec3
#define FfxUInt32x4 uvec4
#define FfxBoolean bool
#if FFX_HALF
#define FfxFloat16 float16_t
#define FfxFloat16x2 f16vec2
#define FfxFloat16x3 f16vec3
#define FfxFloat16x4 f16vec4
#endif
#endif

#define FFX_DOF_INLINE
#define FFX_DOF_OUT(type) out type
#define FFX_DOF_INOUT(type) inout type
#define FFX_DOF_STATIC_CONST const
#define FFX_DOF_GROUPSHARED shared
#define FFX_DOF_UNROLL [[unroll]]
#define FFX_DOF_LOOP [[dont_unroll]]
#define ffxDofGroupBarrier() \
    groupMemoryBarrier();    \
    barrier()

#define ffxDofLerp(a, b, t) mix(a, b, t)
#define ffxDofFract(x) fract(x)
#define ffxDofAsUInt(x) floatBitsToUint(x)
#define ffxDofAsFloat(x) uintBitsToFloat(x)
#define ffxDofPackHalf2(v) packHalf2x16(v)
#define ffxDofUnpackHalf2(bits) unpackHalf2x16(bits)
#define ffxDofWaveMin(x) subgroupMin(x)
#define ffxDofWaveMax(x) subgroupMax(x)
#define ffxDofWaveSum(x) subgroupAdd(x)
#define ffxDofWaveAnyTrue(x) subgroupAny(x)
#define ffxDofWaveAllTrue(x) subgroupAll(x)
#define ffxDofWaveReadFirst(x) subgroupBroadcastFirst(x)
#define ffxDofWaveIsFirstLane() subgroupElect()
// Which wave of the workgroup the invocation runs in, and how many waves the workgroup has.
#define ffxDofWaveIndex(localIndex) gl_SubgroupID
#define ffxDofWaveCount() gl_NumSubgroups
// The invocation's lane in its wave, and how many lanes a wave has.
#define ffxDofWaveLaneIndex() gl_SubgroupInvocationID
#define ffxDofWaveLaneCount() gl_SubgroupSize
// Sets bits of a group-shared word for the whole group, and counts a word's set bits.
#define ffxDofGroupAtomicOr(word, bits) atomicOr(word, bits)
#define ffxDofCountBits(x) FfxUInt32(bitCount(x))
#define ffxDofFirstBitLow(x) FfxUInt32(findLSB(x))

// GLSL has no saturate/rcp; overloads per type keep the literals in the argument's precision.
float ffxDofSaturate(float x) { return clamp(x, 0.0f, 1.0f); }
vec2 ffxDofSaturate(vec2 x) { return clamp(x, vec2(0.0f), vec2(1.0f)); }
vec3 ffxDofSaturate(vec3 x) { return clamp(x, vec3(0.0f), vec3(1.0f)); }
vec4 ffxDofSaturate(vec4 x) { return clamp(x, vec4(0.0f), vec4(1.0f)); }
float ffxDofRcp(float x) { return 1.0f / x; }
vec2 ffxDofRcp(vec2 x) { return vec2(1.0f) / x; }
vec3 ffxDofRcp(vec3 x) { return vec3(1.0f) / x; }
#if FFX_HALF
float16_t ffxDofSaturate(float16_t x) { return clamp(x, float16_t(0.0f), float16_t(1.0f)); }
f16vec2 ffxDofSaturate(f16vec2 x) { return clamp(x, f16vec2(0.0f), f16vec2(1.0f)); }
f16vec3 ffxDofSaturate(f16vec3 x) { return clamp(x, f16vec3(0.0f), f16vec3(1.0f)); }
f16vec4 ffxDofSaturate(f16vec4 x) { return clamp(x, f16vec4(0.0f), f16vec4(1.0f)); }
float16_t ffxDofRcp(float16_t x) { return float16_t(1.0f) / x; }
f16vec3 ffxDofRcp(f16vec3 x) { return f16vec3(1.0f) / x; }
#endif

//==================================================================================================
#elif defined(FFX_HLSL)
//==================================================================================================
#if FFX_DOF_DECLARE_FFX_TYPES
typedef float FfxFloat32;
typedef float2 FfxFloat32x2;
typedef float3 FfxFloat32x3;
typedef float4 FfxFloat32x4;
typedef int FfxInt32;
typedef int2 FfxInt32x2;
typedef int3 FfxInt32x3;
typedef int4 FfxInt32x4;
typedef uint FfxUInt32;
typedef uint2 FfxUInt32x2;
typedef uint3 FfxUInt32x3;
typedef uint4 FfxUInt32x4;
typedef bool FfxBoolean;
#if FFX_HALF
// 'half' is a real 16-bit float under -enable-16bit-types (dxc and glslang); min16float is not
// used because glslang compiles it as 32-bit with a RelaxedPrecision decoration.
typedef half FfxFloat16;
typedef half2 FfxFloat16x2;
typedef half3 FfxFloat16x3;
typedef half4 FfxFloat16x4;
#endif
#endif

#define FFX_DOF_INLINE
#define FFX_DOF_OUT(type) out type
#define FFX_DOF_INOUT(type) inout type
#define FFX_DOF_STATIC_CONST static const
#define FFX_DOF_GROUPSHARED groupshared
#define FFX_DOF_UNROLL [unroll]
#define FFX_DOF_LOOP [loop]
#define ffxDofGroupBarrier() GroupMemoryBarrierWithGroupSync()

#define ffxDofSaturate(x) saturate(x)
#define ffxDofRcp(x) rcp(x)
#define ffxDofLerp(a, b, t) lerp(a, b, t)
#define ffxDofFract(x) frac(x)
#define ffxDofAsUInt(x) asuint(x)
#define ffxDofAsFloat(x) asfloat(x)
#define ffxDofPackHalf2(v) (f32tof16((v).x) | (f32tof16((v).y) << 16u))
#define ffxDofUnpackHalf2(bits) FfxFloat32x2(f16tof32((bits)&0xffffu), f16tof32((bits) >> 16u))
#define ffxDofWaveMin(x) WaveActiveMin(x)
#define ffxDofWaveMax(x) WaveActiveMax(x)
#define ffxDofWaveSum(x) WaveActiveSum(x)
#define ffxDofWaveAnyTrue(x) WaveActiveAnyTrue(x)
#define ffxDofWaveAllTrue(x) WaveActiveAllTrue(x)
#define ffxDofWaveReadFirst(x) WaveReadLaneFirst(x)
#define ffxDofWaveIsFirstLane() WaveIsFirstLane()
// HLSL has no wave index: waves are taken to hold consecutive flattened thread indices, the layout
// every D3D12 driver uses for a one-dimensional group (FidelityFX SPD relies on it too).
#define ffxDofWaveIndex(localIndex) ((localIndex) / WaveGetLaneCount())
#define ffxDofWaveCount() ((FfxUInt32(FFX_DOF_GROUP_THREADS) + WaveGetLaneCount() - 1u) / WaveGetLaneCount())
#define ffxDofWaveLaneIndex() WaveGetLaneIndex()
#define ffxDofWaveLaneCount() WaveGetLaneCount()
#define ffxDofGroupAtomicOr(word, bits) InterlockedOr(word, bits)
#define ffxDofCountBits(x) countbits(x)
#define ffxDofFirstBitLow(x) firstbitlow(x)

//==================================================================================================
#else  // FFX_CPU
//==================================================================================================
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

#if FFX_DOF_DECLARE_FFX_TYPES
typedef float FfxFloat32;
typedef glm::vec2 FfxFloat32x2;
typedef glm::vec3 FfxFloat32x3;
typedef glm::vec4 FfxFloat32x4;
typedef int32_t FfxInt32;
typedef glm::ivec2 FfxInt32x2;
typedef glm::ivec3 FfxInt32x3;
typedef glm::ivec4 FfxInt32x4;
typedef uint32_t FfxUInt32;
typedef glm::uvec2 FfxUInt32x2;
typedef glm::uvec3 FfxUInt32x3;
typedef glm::uvec4 FfxUInt32x4;
typedef bool FfxBoolean;
#if FFX_HALF
// The CPU has no 16-bit float arithmetic worth testing: the 16-bit types are 32-bit here.
typedef float FfxFloat16;
typedef glm::vec2 FfxFloat16x2;
typedef glm::vec3 FfxFloat16x3;
typedef glm::vec4 FfxFloat16x4;
#endif
#endif

// The shader built-ins the shared code calls unqualified.
using glm::abs;
using glm::acos;
using glm::ceil;
using glm::clamp;
using glm::cos;
using glm::dot;
using glm::exp2;
using glm::floor;
using glm::length;
using glm::log2;
using glm::max;
using glm::min;
using glm::pow;
using glm::round;
using glm::sin;
using glm::sqrt;

#define FFX_DOF_INLINE inline
#define FFX_DOF_OUT(type) type&
#define FFX_DOF_INOUT(type) type&
#define FFX_DOF_STATIC_CONST static const
// One workgroup runs at a time on the CPU (see tests/shaders), so group-shared memory is a global
// (an inline variable: one instance however many translation units include the pass).
#define FFX_DOF_GROUPSHARED inline
#define FFX_DOF_UNROLL
#define FFX_DOF_LOOP

// Provided by the CPU harness that runs a workgroup's invocations (tests/shaders/ffx_dof_cpu_runner).
void ffxDofCpuGroupBarrier();
#define ffxDofGroupBarrier() ffxDofCpuGroupBarrier()

template <typename T>
inline T ffxDofSaturate(T x)
{
    return glm::clamp(x, T(0.0f), T(1.0f));
}
template <typename T>
inline T ffxDofRcp(T x)
{
    return T(1.0f) / x;
}
template <typename T, typename U>
inline T ffxDofLerp(T a, T b, U t)
{
    return glm::mix(a, b, t);
}
template <typename T>
inline T ffxDofFract(T x)
{
    return glm::fract(x);
}
inline uint32_t ffxDofAsUInt(float x)
{
    uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
}
inline float ffxDofAsFloat(uint32_t bits)
{
    float x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}
inline uint32_t ffxDofPackHalf2(glm::vec2 v) { return glm::packHalf2x16(v); }
inline glm::vec2 ffxDofUnpackHalf2(uint32_t bits) { return glm::unpackHalf2x16(bits); }
// The CPU runs each invocation as a wave of one lane.
#define ffxDofWaveMin(x) (x)
#define ffxDofWaveMax(x) (x)
#define ffxDofWaveSum(x) (x)
#define ffxDofWaveAnyTrue(x) (x)
#define ffxDofWaveAllTrue(x) (x)
#define ffxDofWaveReadFirst(x) (x)
#define ffxDofWaveIsFirstLane() true
#define ffxDofWaveIndex(localIndex) (localIndex)
#define ffxDofWaveCount() FfxUInt32(FFX_DOF_GROUP_THREADS)
#define ffxDofWaveLaneIndex() 0u
#define ffxDofWaveLaneCount() 1u
// The invocations of a CPU workgroup are threads (tests/shaders): the GCC / Clang builtin, as C++17 has no
// std::atomic_ref for a plain word.
inline void ffxDofGroupAtomicOr(uint32_t& word, uint32_t bits) { __atomic_fetch_or(&word, bits, __ATOMIC_RELAXED); }
inline uint32_t ffxDofCountBits(uint32_t x) { return uint32_t(__builtin_popcount(x)); }
// Of a nonzero word.
inline uint32_t ffxDofFirstBitLow(uint32_t x) { return uint32_t(__builtin_ctz(x)); }

#endif  // language

//==================================================================================================
// Language-independent part.
//==================================================================================================

// The precision the algorithm uses for color and other quantities that tolerate 16 bits. Depth,
// CoC radii, distances and accumulated weights always stay 32-bit.
#if FFX_HALF
#define FfxDofFloat FfxFloat16
#define FfxDofFloat2 FfxFloat16x2
#define FfxDofFloat3 FfxFloat16x3
#define FfxDofFloat4 FfxFloat16x4
#else
#define FfxDofFloat FfxFloat32
#define FfxDofFloat2 FfxFloat32x2
#define FfxDofFloat3 FfxFloat32x3
#define FfxDofFloat4 FfxFloat32x4
#endif

FFX_DOF_INLINE FfxFloat32 ffxDofMad(FfxFloat32 a, FfxFloat32 b, FfxFloat32 c) { return a * b + c; }
FFX_DOF_INLINE FfxFloat32x3 ffxDofBroadcast3(FfxFloat32 x) { return FfxFloat32x3(x, x, x); }
FFX_DOF_INLINE FfxDofFloat3 ffxDofBroadcastDof3(FfxDofFloat x) { return FfxDofFloat3(x, x, x); }
FFX_DOF_INLINE FfxFloat32x3 ffxDofToFloat32x3(FfxDofFloat3 x) { return FfxFloat32x3(x.x, x.y, x.z); }
FFX_DOF_INLINE FfxDofFloat3 ffxDofToDofFloat3(FfxFloat32x3 x) { return FfxDofFloat3(x.x, x.y, x.z); }

#endif  // FFX_DOF_PORTABILITY_H
