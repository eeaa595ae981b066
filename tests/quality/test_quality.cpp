#include "quality_scenes.h"

#include <catch2/catch.hpp>

#include <memory>

using namespace ffxdof;

namespace {

// One device for every gate, with the validation layer on: any message fails the test.
vkrun::Device& sharedDevice() {
    static std::unique_ptr<vkrun::Device> device = [] {
        vkrun::DeviceOptions options;
        options.validation = true;
        return std::make_unique<vkrun::Device>(options);
    }();
    return *device;
}

}  // namespace

TEST_CASE("quality gates per scene against the thin-lens truth", "[quality][vulkan]") {
    for (const quality::SceneGate& gate : quality::sceneGates()) {
        DYNAMIC_SECTION(gate.scene) {
            const quality::SceneRender render = quality::renderScene(gate.scene);
            vkrun::Device& device = sharedDevice();
            device.clearValidationMessages();
            const quality::GateResult result = quality::runGate(device, render);
            INFO("scene " << gate.scene << "\ninput vs truth:\n"
                          << metrics::formatComparison(result.input) << "ffx-dof vs truth:\n"
                          << metrics::formatComparison(result.effect) << "circular gather vs truth:\n"
                          << metrics::formatComparison(result.gather) << "in-focus max |ours - input| "
                          << result.inFocusMaxDifference * 255.0 << "/255 over " << result.inFocusPixels << " px");
            CHECK(device.validationMessages().empty());
            CHECK(result.psnrGate(gate.psnrMarginDb));
            CHECK(result.inFocusGate());
            CHECK(result.inFocusPixels > 0);
            CHECK(result.haloGate());
        }
    }
}

TEST_CASE("the circular gather baseline blurs by each pixel's own radius", "[quality]") {
    io::ImageRGBA color(9, 9);
    color.at(4, 4)[0] = 10.0f;
    io::ImageR radius(9, 9);
    for (float& r : radius.pixels) r = -1.0f;
    radius.at(4, 3) = 0.0f;
    const io::ImageRGBA blurred = quality::circularGatherBaseline(color, radius);
    // A radius of 1 px gathers the pixel and its four neighbours.
    CHECK(blurred.at(4, 4)[0] == Approx(2.0f));
    CHECK(blurred.at(5, 4)[0] == Approx(2.0f));
    CHECK(blurred.at(5, 5)[0] == 0.0f);
    CHECK(blurred.at(4, 3)[0] == 0.0f);  // radius 0: the pixel itself
}

TEST_CASE("bokeh of a single far point: radius, flatness, energy", "[quality][vulkan]") {
    const quality::SceneRender render = quality::renderScene("point");
    vkrun::Device& device = sharedDevice();
    device.clearValidationMessages();
    const quality::GateResult result = quality::runGate(device, render);
    const double expectedRadius =
        std::abs(render.setup.camera.cocRadiusPixels(render.setup.scene.primitives[0].center.z));
    // Energy: ffx-dof spreads the input's energy (the pinhole image), it cannot know the true one.
    const double inputEnergy = metrics::measureBokeh(render.pinhole.color).energy;
    const metrics::BokehMeasurement truth = metrics::measureBokeh(render.truth);
    const metrics::BokehMeasurement ours = metrics::measureBokeh(result.ours);
    const metrics::BokehCheck truthCheck = metrics::checkBokeh(truth, expectedRadius, truth.energy);
    const metrics::BokehCheck check = metrics::checkBokeh(ours, expectedRadius, inputEnergy);
    INFO("truth: " << truthCheck.summary << "\nffx-dof: " << check.summary);
    CHECK(device.validationMessages().empty());
    CHECK(truthCheck.radiusOk);
    CHECK(check.radiusOk);
    CHECK(check.flatOk);
    CHECK(check.energyOk);
}
