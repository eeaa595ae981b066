// Test pass for ffx-dof-shaderc in HLSL: same shape as ffx_dof_test.glsl.
#include "ffx_dof_test_common.h"

struct FfxDofTestConstants {
    float scale;
    uint flags;
    uint2 size;
    float2 texelSize;
};
[[vk::push_constant]] ConstantBuffer<FfxDofTestConstants> ffxDofTestConstants;

Texture2D<float4> ffxDofTestInput : register(t0);
RWTexture2D<float4> ffxDofTestOutput : register(u0);
RWStructuredBuffer<uint> ffxDofTestGlobals : register(u24);  // binding 40 with the u=16 shift

#if FFX_HALF
typedef half FfxDofTestScalar;
typedef half4 FfxDofTestColor;
#else
typedef float FfxDofTestScalar;
typedef float4 FfxDofTestColor;
#endif

#if FFX_DOF_TEST_WIDE
[numthreads(FFX_DOF_TEST_GROUP_SIZE * 8, 1, 1)]
#else
[numthreads(FFX_DOF_TEST_GROUP_SIZE, FFX_DOF_TEST_GROUP_SIZE, 1)]
#endif
void main(uint3 id : SV_DispatchThreadID) {
    if (any(id.xy >= ffxDofTestConstants.size)) return;
    FfxDofTestColor color = FfxDofTestColor(ffxDofTestInput.Load(int3(id.xy, 0))) * FfxDofTestScalar(float(FFX_DOF_TEST_SCALE));
    ffxDofTestOutput[id.xy] = float4(color) * ffxDofTestConstants.scale;
    uint previous;
    InterlockedMax(ffxDofTestGlobals[0], ffxDofTestConstants.flags + FFX_DOF_TEST_SCALE, previous);
}
