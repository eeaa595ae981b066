// Issue 17's light-keeping gates on its minimal case: a small light between the focus and a much
// farther background keeps its energy and spreads into a disc of the truth's level, at every size from
// 1 to 15 px and at radii from 6 to 28 px (sizes 1 to 5 px at radii 2 to 4 px), at three places in the
// MIP grids, in 16- and 32-bit (quality_scenes.h).
#include "quality_scenes.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <vector>

using namespace ffxdof;

namespace {

// Issue 17's two gates on every light: the energy it adds within 5% of what it adds to the input, and its centre
// within 20% of the truth's; and no validation message on the way.
void checkEveryLight(const std::vector<quality::SmallLightCase>& lights, size_t expectedCount) {
    REQUIRE(lights.size() == expectedCount);
    for (const quality::SmallLightCase& light : lights) {
        INFO(light.describe());
        CHECK(light.energyOk());
        CHECK(light.centreOk());
    }
    CHECK(quality::validatedDevice().validationMessages().empty());
}

}  // namespace

// Both gates in one test case, so the 362 runs happen once (CTest runs each test case in a process of its own).
TEST_CASE(
    "small lights: the energy a light adds within 5% of what it adds to the input, and its centre within 20% "
    "of the truth's, radii 6 to 28 px",
    "[quality][vulkan][lights]") {
    // Every case, since a coarse texel's light is drawn about where it lies in the texel (its light offset,
    // docs/technique.md "Light offsets"): 0.95 to 1.03 (docs/quality.md, small lights). Drawn about the
    // coarse texel's centre, one case of 240 failed (a 7 px light at radius 6 px, 16-bit, offset (6, 5): 1.051).
    quality::validatedDevice().clearValidationMessages();
    checkEveryLight(quality::runSmallLightCases(quality::validatedDevice()),
                    std::size(quality::kSmallLightSizes) * std::size(quality::kSmallLightRadii) *
                        std::size(quality::kSmallLightOffsets) * 2);
}

// Issue 17 asks the same at every depth between the focus and the background, so below the gated radii too (2 to
// 4 px: the composite blurs the light's own pixels at full resolution, the background around them takes the
// half-res layers). Measured 2026-11-28: 16 of 72 cases within 5% (a 1 px light at 2 px kept 0.51, others gained up
// to 27%); 56 since tiles that may hold such lights above white draw them at full resolution
// (ffx_dof_small_sources.h), 66 since the downsample weighs radii by squared light (a light's coarse texels keep its
// radius), all 72 since the composite normalises those discs by their area on the pixel grid (ffxDofPixelDiscArea):
// docs/quality.md, small lights.
TEST_CASE("small lights below radius 6 px: the energy a light adds within 5% of what it adds to the input",
          "[quality][vulkan][lights]") {
    quality::validatedDevice().clearValidationMessages();
    checkEveryLight(quality::runSmallLightCasesBelowGate(quality::validatedDevice()), 72);
}

// Issue 17: "for every light, the energy it adds ... within 5%", in the scene itself (docs/quality.md,
// "lights of the mid-lights scene"). Measured 2026-11-28: 7 of 14 lights pass since rings merge only where the
// smallest radius spans two coarse texels (5 with one texel, 3 before the light rims). Since a coarse texel's light
// is drawn about where it lies in the texel (its light offset) light 2 keeps 1.01 within its own disc and 0.91 over the
// frame (-1.62 before: it changes light 3's disc less); light 0 (at 2.8 px) kept 0.86, and passes (1.02) since
// tiles that may hold small lights above white draw them at full resolution (8 of 14); the partly hidden ones add
// 0.81 to 2.10 times the truth's (light 8, the faintest, 1.42 since radii are weighed by squared light). Since lights
// above white are drawn at full resolution (ffx_dof_highlights.h, 2026-11-30) 11 of 14 pass: lights 12 and 13, half
// behind the box, add 0.88 and 0.86 of the truth's (the thin lens sees around the box), light 6 0.80. Until every
// light passes, the count of passing lights is a ratchet: it may rise (raise kLightsWithinFivePercent with it), never
// fall. One test case, so the 28 runs happen once.
TEST_CASE("mid-lights: every light measured alone, and no fewer lights within 5% than measured",
          "[quality][vulkan][lights]") {
    constexpr size_t kLightsWithinFivePercent = 11;  // of 14, in both precisions
    quality::validatedDevice().clearValidationMessages();
    const std::vector<quality::SceneLightCase> lights =
        quality::runSceneLightCases(quality::validatedDevice(), "mid-lights");
    // 14 emitters, each in both precisions; the last two sit beside the box, partly hidden by it.
    REQUIRE(lights.size() == 28);
    size_t passing = 0;
    for (const quality::SceneLightCase& light : lights) {
        INFO(light.describe());
        CHECK(light.inputAdded > 0.0);
        CHECK(light.radius < -1.0);
        if (light.emitter >= 12) CHECK(light.partlyHidden);
        if (light.partlyHidden) CHECK(light.truthAdded < light.inputAdded * 1.05);
        if (!light.float32) {
            bool bothOk = light.energyOk();
            for (const quality::SceneLightCase& other : lights)
                if (other.float32 && other.emitter == light.emitter) bothOk = bothOk && other.energyOk();
            passing += bothOk ? 1 : 0;
        }
    }
    CHECK(passing >= kLightsWithinFivePercent);
    CHECK(quality::validatedDevice().validationMessages().empty());
}

// The mid-lights scene's non-locality in its minimal case (quality_scenes.h, LightPairCase): alone the dim
// light adds 1.00 to 1.02 of its input; beside the bright light 0.97 to 1.02 (2026-11-29), with ring merging
// and without. History (docs/quality.md has it in full): merged texels drew the bright disc about coarse texel
// centres (the dim light lost 7 to 19% from 24 px on, until 2026-11-28); the dim light's own texels never read
// the bright light beyond their kernel (0.79 to 0.82 at 16 px, until 2026-11-28, ffxDofGatherBehind); the
// composite's upsample rejected far texels of another radius (0.91 to 0.94, until 2026-11-29,
// ffxDofUpsampleCocWeight); the walk beyond the kernel read the bright light at MIP 0, at its texels'
// centres (0.92 to 0.94, until 2026-11-29, ffxDofBehindMip).
TEST_CASE("small lights: a dim light beside a bright one adds its energy within 5%", "[quality][vulkan][lights]") {
    quality::validatedDevice().clearValidationMessages();
    const std::vector<quality::LightPairCase> pairs = quality::runLightPairCases(quality::validatedDevice());
    REQUIRE(pairs.size() == 12);
    for (const quality::LightPairCase& pair : pairs) {
        INFO(pair.describe());
        CHECK(pair.energyOk());
    }
    CHECK(quality::validatedDevice().validationMessages().empty());
}

// The diagnostic behind docs/quality.md's partly hidden lights (ffx_dof_quality_report_tool --light-profile).
TEST_CASE("mid-lights: a light's profile holds what it adds around it, clipped to the frame",
          "[quality][vulkan][lights]") {
    vkrun::Device& device = quality::validatedDevice();
    device.clearValidationMessages();
    const auto sum = [](const std::vector<double>& values) {
        double total = 0.0;
        for (double value : values) total += value;
        return total;
    };
    // Light 3 (radius 18.2 px, not hidden) over the whole frame: ffx-dof adds what the input does, within 5%.
    const quality::LightProfile whole = quality::measureLightProfile(device, "mid-lights", 3, 400);
    CHECK(whole.x0 == 0);
    CHECK(whole.y0 == 0);
    CHECK(whole.width == int(quality::kWidth));
    CHECK(whole.height == int(quality::kHeight));
    CHECK(whole.radius == Approx(-18.2).margin(0.1));
    REQUIRE(sum(whole.inputAdded) > 0.0);
    CHECK(sum(whole.oursAdded) / sum(whole.inputAdded) == Approx(1.0).margin(0.05));
    // Light 6 (radius 2.8 px): a window of 5 px each way holds all of its input's share, and the pixels of its
    // disc, all far.
    const quality::LightProfile near = quality::measureLightProfile(device, "mid-lights", 6, 5);
    const quality::LightProfile wide = quality::measureLightProfile(device, "mid-lights", 6, 30);
    CHECK(near.width == 11);
    CHECK(near.height == 11);
    REQUIRE(near.inputAdded.size() == 121u);
    CHECK(near.radius == Approx(-2.76).margin(0.05));
    CHECK(sum(near.inputAdded) == Approx(sum(wide.inputAdded)).epsilon(1e-6));
    CHECK(sum(near.oursAdded) == Approx(sum(wide.oursAdded)).epsilon(0.01));
    CHECK(near.pixelRadius[60] < -1.0);  // the window's centre
    CHECK_THROWS_AS(quality::measureLightProfile(device, "mid-lights", 14, 5), std::invalid_argument);
    CHECK_THROWS_AS(quality::measureLightProfile(device, "mid-lights", 6, -1), std::invalid_argument);
    CHECK(device.validationMessages().empty());
}

// Near lights over an in-focus background (quality_scenes.h, runNearLightCases): every light, 1 px ones included,
// keeps its energy within 5% (docs/quality.md, near lights). Until 2026-11-30 such lights vanished or drew up to 1.48
// times their energy, and then 1 px lights at radius 8 px kept 0.93 of it, until the composite drew the near
// layer's rim over in-focus pixels.
TEST_CASE("small near lights: the energy a light adds within 5% of what it adds to the input, none vanishes",
          "[quality][vulkan][lights]") {
    const std::vector<quality::SmallLightCase> lights = quality::runNearLightCases(quality::validatedDevice());
    REQUIRE(lights.size() == std::size(quality::kNearLightRadii) * std::size(quality::kNearLightSizes) *
                                 std::size(quality::kSmallLightOffsets) * 2);
    for (const quality::SmallLightCase& light : lights) {
        INFO(light.describe());
        CHECK(light.near);
        CHECK(light.energyOk());
    }
    CHECK(quality::validatedDevice().validationMessages().empty());
}
