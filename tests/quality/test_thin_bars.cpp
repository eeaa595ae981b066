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
        INFO(bar.describe());
        CHECK(bar.opacityOk());
        CHECK(bar.stepOk());
    }
    CHECK(quality::validatedDevice().validationMessages().empty());
}
