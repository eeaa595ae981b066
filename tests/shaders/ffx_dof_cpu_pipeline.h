// Runs the five passes of shaders_common on the CPU through the C++ mapping: the accessors are
// backed by std::vector images, and each workgroup runs as 64 threads meeting at a real barrier.
#pragma once

#include "ffx_dof.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace ffxdoftest {

struct Scene {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<glm::vec4> color;  // linear, row-major
    std::vector<float> depth;      // device depth; radius = depth * cocScale + cocBias
};

struct Settings {
    float cocScale = -1.0f;
    float cocBias = 0.0f;
    float cocLimit = 32.0f;
    uint32_t maxRings = 10;
    uint32_t frameIndex = 0;
    // Runs every blur tile on the mixed path instead of its class's (ffxDofBlurTileClass): the
    // reference the cheaper paths are compared with.
    bool forceMixedBlurPath = false;
    // Runs every composite tile of class FULL_RES on the LIGHTS path (ffxDofCompositeTileClass): the reference the
    // class without the lights' code is compared with.
    bool forceLightsCompositePath = false;
    // The aperture, as FfxDofDispatchDescription::pAperture gives it (the SDK sets the constants).
    FfxDofAperture aperture{0, 0.0f, 0.0f, 1.0f, 0.0f};
};

struct Layers {
    uint32_t halfWidth = 0, halfHeight = 0, tilesX = 0, tilesY = 0;
    std::vector<glm::vec2> tiles;            // pass 1
    std::vector<float> tileColorPeaks;       // pass 2: each tile's colour peak (HIGHLIGHTS)
    std::vector<glm::vec4> dilatedTiles;     // pass 3: far, near, footprint min, footprint max
    std::vector<uint32_t> tileClasses;       // pass 4: FFX_DOF_BLUR_CLASS_* of each tile (as classified)
    std::vector<uint32_t> blurTileFlags;     // pass 3: FFX_DOF_LISTED_TILE_* of each tile's blur list entry
    std::vector<uint32_t> compositeClasses;  // pass 3: FFX_DOF_COMPOSITE_CLASS_* of each tile (the list it is in)
    std::vector<float> coc0;                 // MIP 0 of COC_MIPS
    std::vector<glm::vec3> nearColor, farColor;
    std::vector<glm::vec2> layerAlpha;
    float globalMaxRadius = 0.0f;        // GLOBALS after pass 1
    uint32_t globalsAfterComposite = 1;  // GLOBALS words 0 and 1 after pass 5, or-ed (must be 0)
    float colorPeak = 0.0f;              // GLOBALS colour peak after pass 2 (0 unless above the limit)
    bool colorRangeRerun = false;        // pass 2's first run armed its second (a channel above the limit)
    float colorScale = 0.0f;             // GLOBALS colour scale after pass 2
};

std::vector<glm::vec4> runPipeline(const Scene& scene, const Settings& settings, Layers* layers = nullptr);

// Issue 17's minimal case at half-res radii: a square light of value 50 at radius -10.4 in front of a
// background of 0.05 at -16, 1 to 13 px wide. Before the far field was composed as layers, the
// light's centre kept its input value (the ring occlusion let it hide its whole kernel), and a 1 or
// 3 px light vanished in the bilateral downsample (dropped as an outlier at every MIP).
struct LightCase {
    int size = 0;              // px per side
    double inputEnergy = 0.0;  // what the light adds to the input (green channel, summed)
    double energyAdded = 0.0;  // what it adds to the output
    double centre = 0.0;       // output at the light's centre
    double discLevel = 0.0;    // thin lens: its energy over its disc, over the background it leaves
};
// `lightRadius` (half-res px, in front of the background at 16) and the light's sizes (px per side).
std::vector<LightCase> runSmallFarLightCases(float lightRadius = 10.4f,
                                             const std::vector<int>& sizes = {1, 3, 5, 9, 13});

// A single far pixel of `value` on black, both at far radius `radius` (half-res px), at one of two
// positions in the quad grid: the energy of the half-res far layer (value / 4: a quarter of one
// half-res texel's light) and its flatness (std / mean within 0.7 R of the point).
struct PointDisc {
    double energy = 0.0;
    double flatness = 0.0;
};
PointDisc measurePointDisc(float radius, int position, uint32_t frame, float value = 10.0f);

}  // namespace ffxdoftest
