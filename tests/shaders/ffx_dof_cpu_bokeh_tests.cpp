// The single-point bokeh of issue 6 on the CPU, built with FFX_DOF_OPTION_DISABLE_RING_MERGE 1 (the
// FFX_DOF_DISABLE_RING_MERGE permutation): every ring of the kernel read from one MIP, so every texel
// of the kernel is read exactly once and a one-texel source makes a flat disc of its own energy.
#include <catch2/catch.hpp>

#include "ffx_dof_common.h"
#include "ffx_dof_cpu_pipeline.h"

#include <algorithm>
#include <cmath>

static_assert(FFX_DOF_OPTION_DISABLE_RING_MERGE == 1, "built without ring merging");

TEST_CASE("A single bright far pixel spreads into a flat disc of its energy (half-res far layer)", "[pipeline]") {
    // Ring points read from the nearest texel hit the one texel holding the point 0 to 2 times
    // depending on the output texel: with them, this far layer measured flatnesses (std / mean within
    // 0.7 R) of 0.04 to 0.47 and energies 2.2 to 2.8.
    for (const float radius : {2.0f, 4.8f, 9.0f}) {
        // A light above white is drawn by the composite at full resolution, not in this layer (below
        // FFX_DOF_FAR_LAYER_ONLY_RADIUS ffx_dof_small_sources.h, from it ffx_dof_highlights.h): the point is one
        // at white.
        const float value = 1.0f;
        for (int position = 0; position < 2; ++position) {
            for (uint32_t frame = 0; frame < 2; ++frame) {
                const ffxdoftest::PointDisc disc = ffxdoftest::measurePointDisc(radius, position, frame, value);
                INFO("radius " << radius << ", position " << position << ", frame " << frame << ": energy "
                               << disc.energy << ", flatness " << disc.flatness);
                // The disc's rim is anti-aliased by the reach (half a pixel each side), which the
                // kernel's edge, (rings + 1/2) spacing from the jittered origin, cuts a little.
                CHECK(disc.energy == Approx(value / 4.0f).epsilon(0.03));
                CHECK(disc.flatness < 0.03);
            }
        }
    }
}

TEST_CASE("A small far light in front of a farther background keeps its energy (no ring merging)", "[pipeline]") {
    for (const ffxdoftest::LightCase& light : ffxdoftest::runSmallFarLightCases()) {
        INFO("light " << light.size << " px: energy added " << light.energyAdded << " of " << light.inputEnergy
                      << ", centre " << light.centre << " (disc level " << light.discLevel << ")");
        CHECK(light.energyAdded == Approx(light.inputEnergy).epsilon(0.05));
        CHECK(light.centre == Approx(light.discLevel).epsilon(0.20).margin(0.05));
    }
}
