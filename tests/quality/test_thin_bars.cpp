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

TEST_CASE("thin near bars narrower than a half-res texel, or of 2 px at radius 40 - known failure",
          "[quality][vulkan][bars][!shouldfail]") {
    // A 1 px bar takes its quad's whole half-res texel or none of it (the downsample keeps the pixels
    // of the quad's reference radius): 2 px of opacity from an even column, none from an odd one,
    // where at radius 40 the bar's own pixel keeps 0.42 of its input, a hard line. At radius 40 the
    // inner rings read MIP levels whose texels hold a 2 px bar the same way (docs/quality.md).
    for (const quality::ThinBarCase& bar : allThinBars()) {
        if (!bar.knownFailure()) continue;
        INFO(bar.describe());
        CHECK(bar.opacityOk());
        CHECK(bar.stepOk());
    }
}
