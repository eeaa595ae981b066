// Runs the five passes of shaders_common on the CPU through the C++ mapping: the accessors are
// backed by std::vector images, and each workgroup runs as 64 threads meeting at a real barrier.
#pragma once

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
    // Runs every blur tile on the mixed path instead of its class's (ffxDofClassifyTile): the
    // reference the cheaper paths are compared with.
    bool forceMixedBlurPath = false;
};

struct Layers {
    uint32_t halfWidth = 0, halfHeight = 0, tilesX = 0, tilesY = 0;
    std::vector<glm::vec2> tiles;         // pass 1
    std::vector<glm::vec4> dilatedTiles;  // pass 3: far, near, footprint min, footprint max
    std::vector<uint32_t> tileClasses;    // pass 4: FFX_DOF_TILE_CLASS_* of each tile (as classified)
    std::vector<float> coc0;              // MIP 0 of COC_MIPS
    std::vector<glm::vec3> nearColor, farColor;
    std::vector<glm::vec2> layerAlpha;
    float globalMaxRadius = 0.0f;        // GLOBALS after pass 1
    uint32_t globalsAfterComposite = 1;  // GLOBALS words 0 and 1 after pass 5, or-ed (must be 0)
    float colorPeak = 0.0f;              // GLOBALS colour peak after pass 1 (0 unless above the limit)
    float colorScale = 0.0f;             // GLOBALS colour scale after pass 2
};

std::vector<glm::vec4> runPipeline(const Scene& scene, const Settings& settings, Layers* layers = nullptr);

}  // namespace ffxdoftest
