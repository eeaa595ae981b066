#version 450
// The benchmark's device floor: one full-resolution pass that reads color and depth and writes the
// output, with nothing else. Depth takes part so that its read is not optimized away.
#extension GL_EXT_samplerless_texture_functions : require

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform texture2D ffxDofCopyColor;
layout(set = 0, binding = 1) uniform texture2D ffxDofCopyDepth;
layout(set = 0, binding = 2) uniform writeonly image2D ffxDofCopyOutput;

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(ffxDofCopyOutput)))) return;
    vec4 color = texelFetch(ffxDofCopyColor, pixel, 0);
    const float depth = texelFetch(ffxDofCopyDepth, pixel, 0).r;
    if (depth < 0.0) color = vec4(0.0);
    imageStore(ffxDofCopyOutput, pixel, color);
}
