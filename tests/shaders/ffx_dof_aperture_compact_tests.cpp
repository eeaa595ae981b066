// The compact gauge (FFX_DOF_APERTURE_SHAPES_COMPACT, the blur the core runs for apertures without
// cat's eye whose blades fold to at most two sides) against every side of the polygon, and the rule
// the core chooses it by (ffxDofApertureGaugeIsCompact).
#include <catch2/catch.hpp>

#include "ffx_dof_aperture.h"
#include "ffx_dof_aperture_test_support.h"

static_assert(FFX_DOF_GAUGE_SIDES == FFX_DOF_COMPACT_BLADE_SIDES && FFX_DOF_GAUGE_CAT_EYE == 0,
              "this test is built with the compact gauge");

using namespace ffxdof::testing;

TEST_CASE("The compact gauge is the largest over every side for the apertures the core runs it for", "[aperture]") {
    uint32_t compactCounts = 0;
    for (uint32_t blades = 0; blades <= 16; ++blades) {
        if (blades == 1 || blades == 2) continue;
        for (const float rotation : {0.0f, 17.0f, -100.0f}) {
            for (const float roundness : {0.0f, 0.4f}) {
                for (const float anamorphic : {1.0f, 1.5f, 0.5f}) {
                    const FfxDofAperture aperture = makeAperture(blades, rotation, roundness, anamorphic);
                    const double largestError = largestBladeGaugeError(aperture);
                    INFO(blades << " blades, rotation " << rotation << ", roundness " << roundness << ", anamorphic "
                                << anamorphic << ": largest relative error " << largestError);
                    if (ffxDofApertureGaugeIsCompact(blades, 0.0f)) {
                        CHECK(largestError < 1e-5);
                    } else if (roundness == 0.0f) {
                        // Straight blades the compact gauge cannot carry: it misses sides, so the core must
                        // never run it for them.
                        CHECK(largestError > 1e-3);
                    }
                }
            }
        }
        if (ffxDofApertureGaugeIsCompact(blades, 0.0f)) ++compactCounts;
    }
    CHECK(compactCounts == 4);                            // none, 3, 4 and 6 blades
    CHECK_FALSE(ffxDofApertureGaugeIsCompact(0, 0.25f));  // any cat's eye takes the general gauge
    CHECK_FALSE(ffxDofApertureGaugeIsCompact(6, 1e-6f));
}
