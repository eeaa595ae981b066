// Issue 17's thin near objects: a bar a few pixels wide far in front of the focus is a faint, soft
// veil in the truth, whose opacity summed across the bar is the bar's width (quality_scenes.h).
#include "quality_scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace ffxdof;

namespace {

const std::vector<quality::ThinBarCase>& allThinBars() {
    static const std::vector<quality::ThinBarCase> cases = quality::runThinBarCases(quality::validatedDevice());
    return cases;
}

}  // namespace

TEST_CASE(
    "thin near bars: the veil's opacity summed across the bar within 10% of its width, no step larger "
    "than the truth's",
    "[quality][vulkan][bars]") {
    quality::validatedDevice().clearValidationMessages();
    for (const quality::ThinBarCase& bar : allThinBars()) {
        if (bar.knownFailure()) continue;
        INFO(bar.describe());
        CHECK(bar.opacityOk());
        CHECK(bar.stepOk());
    }
    CHECK(quality::validatedDevice().validationMessages().empty());
}

TEST_CASE("thin near bars of 1 and 2 px at radius 40 - known failure", "[quality][vulkan][bars][!shouldfail]") {
    // At radius 40 the inner rings read MIP levels 1 to 3, whose texels reduce a quad bilaterally: a bar of
    // 1 or 2 px fills its coarse texel or vanishes there, depending on its column (MIP 0 keeps a partly
    // near quad's coverage: docs/technique.md, Near coverage; docs/quality.md).
    for (const quality::ThinBarCase& bar : allThinBars()) {
        if (!bar.knownFailure()) continue;
        INFO(bar.describe());
        CHECK(bar.opacityOk());
        CHECK(bar.stepOk());
    }
}
