// The single-point bokeh of issue 6 on the CPU, built with FFX_DOF_OPTION_MAX_RING_MERGE_LOG 0 (the
// FFX_DOF_DISABLE_RING_MERGE permutation): every ring of the kernel read from one MIP, so every texel
// of the kernel is read exactly once and a one-texel source makes a flat disc of its own energy.
#include <catch2/catch.hpp>

#include "ffx_dof_cpu_pipeline.h"

#include <algorithm>
#include <cmath>

static_assert(FFX_DOF_OPTION_MAX_RING_MERGE_LOG == 0, "built without ring merging");

TEST_CASE("A single bright far pixel spreads into a flat disc of its energy (half-res far layer)", "[pipeline]") {
    // Ring points read from the nearest texel hit the one texel holding the point 0 to 2 times
    // depending on the output texel: with them, this far layer measured flatnesses (std / mean within
    // 0.7 R) of 0.04 to 0.47 and energies 2.2 to 2.8.
    for (const float radius : {2.0f, 4.8f, 9.0f}) {
        for (int position = 0; position < 2; ++position) {
            const uint32_t width = 96, height = 80;
            const int px = 48 + position, py = 40 + 3 * position;
            ffxdoftest::Scene scene;
            scene.width = width;
            scene.height = height;
            scene.color.assign(size_t(width) * height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
            scene.depth.assign(size_t(width) * height, radius);  // radius = -depth: far field
            scene.color[size_t(py) * width + size_t(px)] = glm::vec4(10.0f, 10.0f, 10.0f, 1.0f);
            for (uint32_t frame = 0; frame < 2; ++frame) {
                ffxdoftest::Settings settings;
                settings.frameIndex = frame;
                ffxdoftest::Layers layers;
                ffxdoftest::runPipeline(scene, settings, &layers);
                // The point's light, 10, is a quarter of one half-res texel's: 2.5 over pi R^2.
                double energy = 0.0, sum = 0.0, sum2 = 0.0, count = 0.0;
                for (uint32_t y = 0; y < layers.halfHeight; ++y) {
                    for (uint32_t x = 0; x < layers.halfWidth; ++x) {
                        const size_t i = size_t(y) * layers.halfWidth + x;
                        const double value = layers.farColor[i].x * layers.layerAlpha[i].y;
                        energy += value;
                        const double dx = x + 0.5 - (px + 0.5) / 2.0, dy = y + 0.5 - (py + 0.5) / 2.0;
                        if (dx * dx + dy * dy > 0.49 * radius * radius) continue;
                        sum += value, sum2 += value * value, count += 1.0;
                    }
                }
                const double mean = sum / count;
                const double flatness = std::sqrt(std::max(0.0, sum2 / count - mean * mean)) / mean;
                INFO("radius " << radius << ", point " << px << ", " << py << ", frame " << frame << ": energy "
                               << energy << ", flatness " << flatness);
                // The disc's rim is anti-aliased by the reach (half a pixel each side), which the
                // kernel's edge, (rings + 1/2) spacing from the jittered origin, cuts a little.
                CHECK(energy == Approx(2.5).epsilon(0.03));
                CHECK(flatness < 0.03);
            }
        }
    }
}
