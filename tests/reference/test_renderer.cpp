#include "ffx_dof_metrics.h"
#include "emitter_scene.h"
#include "ffx_dof_reference.h"

#include <nlohmann/json.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace ffxdof;

namespace {

// One small bright emitter (pinhole image radius 0.4 px: a point for the purpose of the test) on
// black at view depth z in the frame's centre, the camera focused at `focus`.
ref::SceneSetup pointScene(uint32_t size, double focus, double z, double aperture) {
    return reftest::emitterScene(size, focus, z, aperture, 0.5 * size, 0.5 * size);
}

}  // namespace

TEST_CASE("a point emitter renders to a disc of the thin-lens CoC radius, flat, energy conserved", "[renderer]") {
    struct Case {
        double focus, z, aperture;
    };
    // Far field (behind focus) and near field (in front), radii from about 6 to 17 px at 64x64.
    const Case cases[] = {{3.0, 20.0, 0.4}, {3.0, 10.0, 0.8}, {5.0, 2.0, 0.4}};
    for (const Case& c : cases) {
        const ref::SceneSetup setup = pointScene(64, c.focus, c.z, c.aperture);
        const double expectedRadius = std::abs(setup.camera.cocRadiusPixels(c.z));
        INFO("focus " << c.focus << " z " << c.z << " expected radius " << expectedRadius);
        REQUIRE(expectedRadius > 5.0);
        REQUIRE(expectedRadius < 20.0);
        ref::RenderSettings settings;
        settings.lensSamples = 64;
        const ref::PinholeImages pinhole = ref::renderPinhole(setup.scene, setup.camera, settings);
        const ref::ThinLensImage truth = ref::renderThinLens(setup.scene, setup.camera, settings);
        // The emitter's energy is its emission times its projected area (0.4 px radius); the 4x4
        // pinhole image only approximates that for a sub-pixel emitter, the lens sampling converges.
        const double expectedEnergy = 100.0 * M_PI * 0.4 * 0.4;
        CHECK(metrics::measureBokeh(pinhole.color).energy == Approx(expectedEnergy).epsilon(0.6));
        const metrics::BokehMeasurement disc = metrics::measureBokeh(truth.color);
        const metrics::BokehCheck check = metrics::checkBokeh(disc, expectedRadius, expectedEnergy, {0.75, 0.08, 0.03});
        INFO(check.summary);
        CHECK(check.ok());
        CHECK(disc.centerX == Approx(32.0).margin(0.25));
        CHECK(disc.centerY == Approx(32.0).margin(0.25));
    }
}

TEST_CASE("with a zero aperture the thin-lens image equals the pinhole image", "[renderer]") {
    ref::SceneSetup setup = ref::makeScene("near-object", 64, 40);
    setup.camera.apertureRadius = 0.0;
    ref::RenderSettings settings;
    settings.lensSamples = 64;
    const ref::PinholeImages pinhole = ref::renderPinhole(setup.scene, setup.camera, settings);
    const ref::ThinLensImage truth = ref::renderThinLens(setup.scene, setup.camera, settings);
    // Both use the same 4x4 sub-pixel positions, so without a lens they agree up to float rounding.
    CHECK(metrics::maxAbsDifference(pinhole.color, truth.color) < 1e-5);
    // With the scene's real aperture they differ a lot: the comparison above can fail.
    const ref::SceneSetup blurred = ref::makeScene("near-object", 64, 40);
    CHECK(metrics::psnr(pinhole.color, ref::renderThinLens(blurred.scene, blurred.camera, settings).color) < 30.0);
}

TEST_CASE("depth outputs follow the projection", "[renderer]") {
    const ref::SceneSetup setup = ref::makeScene("busy-background", 48, 32);
    const ref::PinholeImages images = ref::renderPinhole(setup.scene, setup.camera);
    const ref::ProjectionTerms standard = setup.camera.projection();
    const ref::ProjectionTerms reversed = setup.camera.reversedProjection();
    CHECK(standard.deviceDepth(setup.camera.nearPlane) == Approx(0.0).margin(1e-12));
    CHECK(standard.deviceDepth(setup.camera.farPlane) == Approx(1.0));
    CHECK(reversed.deviceDepth(setup.camera.nearPlane) == Approx(1.0));
    CHECK(reversed.deviceDepth(setup.camera.farPlane) == Approx(0.0).margin(1e-12));
    // The background wall is perpendicular to the axis at 12 m: every corner pixel sees Z = 12 exactly.
    CHECK(images.depth.at(0, 0) == Approx(12.0).epsilon(1e-6));
    CHECK(images.depth.at(47, 31) == Approx(12.0).epsilon(1e-6));
    // The sphere of radius 0.22 centred 2 m away is in front of it near the centre.
    CHECK(images.depth.at(24, 16) < 2.0);
    for (size_t i = 0; i < images.depth.pixels.size(); ++i) {
        const double z = images.depth.pixels[i];
        REQUIRE(z > setup.camera.nearPlane);
        REQUIRE(z <= setup.camera.farPlane);
        REQUIRE(images.deviceDepth.pixels[i] == Approx(standard.deviceDepth(z)).margin(1e-6));
        REQUIRE(images.deviceDepthReversed.pixels[i] == Approx(reversed.deviceDepth(z)).margin(1e-6));
        REQUIRE(standard.viewDepth(images.deviceDepth.pixels[i]) == Approx(z).epsilon(1e-3));
        REQUIRE(reversed.viewDepth(images.deviceDepthReversed.pixels[i]) == Approx(z).epsilon(1e-3));
    }
}

TEST_CASE("the convergence figure falls as lens samples grow", "[renderer]") {
    const ref::SceneSetup setup = ref::makeScene("busy-background", 48, 32);
    ref::RenderSettings settings;
    settings.lensSamples = 8;
    const double coarse = ref::renderThinLens(setup.scene, setup.camera, settings).convergenceRms;
    settings.lensSamples = 128;
    const double fine = ref::renderThinLens(setup.scene, setup.camera, settings).convergenceRms;
    INFO("8 samples " << coarse << ", 128 samples " << fine);
    CHECK(fine < 0.5 * coarse);
    CHECK(fine > 0.0);
    settings.lensSamples = 1;
    CHECK(std::isnan(ref::renderThinLens(setup.scene, setup.camera, settings).convergenceRms));
}

TEST_CASE("renders are deterministic and independent of the thread count", "[renderer]") {
    const ref::SceneSetup setup = ref::makeScene("fence", 40, 24);
    ref::RenderSettings settings;
    settings.lensSamples = 16;
    settings.threads = 1;
    const ref::ThinLensImage single = ref::renderThinLens(setup.scene, setup.camera, settings);
    settings.threads = 3;
    const ref::ThinLensImage multi = ref::renderThinLens(setup.scene, setup.camera, settings);
    CHECK(single.color.pixels == multi.color.pixels);
}

TEST_CASE("every built-in scene renders, with the blur the catalogue promises", "[renderer]") {
    const std::vector<ref::SceneInfo> scenes = ref::listScenes();
    REQUIRE(scenes.size() >= 5);
    for (const ref::SceneInfo& info : scenes) {
        INFO(info.name);
        const ref::SceneSetup setup = ref::makeScene(info.name, 32, 18);
        CHECK(setup.name == info.name);
        const ref::PinholeImages images = ref::renderPinhole(setup.scene, setup.camera);
        for (float value : images.color.pixels) REQUIRE(std::isfinite(value));
    }
    // (d): the background is blurred by 40 full-resolution pixels or more at any size.
    for (uint32_t width : {64u, 320u, 1920u}) {
        const ref::SceneSetup busy = ref::makeScene("busy-background", width, width * 9 / 16);
        CHECK(std::abs(busy.camera.cocRadiusPixels(12.0)) >= 40.0 - 1e-9);
    }
    CHECK_THROWS_WITH(ref::makeScene("nope", 8, 8), Catch::Contains("fence") && Catch::Contains("unknown scene"));
}

TEST_CASE("camera JSON round-trips and rejects impossible lenses", "[renderer][camera]") {
    ref::Camera camera = ref::makeScene("floor", 320, 180).camera;
    const nlohmann::json json = ref::cameraToJson(camera);
    const ref::Camera back = ref::cameraFromJson(json);
    CHECK(back.width == camera.width);
    CHECK(back.position == camera.position);
    CHECK(back.target == camera.target);
    CHECK(back.focalLength == camera.focalLength);
    CHECK(back.apertureRadius == camera.apertureRadius);
    CHECK(json.at("projection").at("proj33").get<double>() == camera.projection().proj33);
    CHECK(json.at("fstop").get<double>() == Approx(camera.focalLength / (2.0 * camera.apertureRadius)));

    nlohmann::json bad = json;
    bad["focusDistance"] = 0.01;  // closer than the focal length
    CHECK_THROWS_WITH(ref::cameraFromJson(bad), Catch::Contains("focusDistance"));
    bad = json;
    bad.erase("sensorWidth");
    CHECK_THROWS_WITH(ref::cameraFromJson(bad), Catch::Contains("sensorWidth"));
    bad = json;
    bad["far"] = 0.05;
    CHECK_THROWS_WITH(ref::cameraFromJson(bad), Catch::Contains("near and far"));

    // A vertical field of view sets the focal length so that the field of view comes back.
    camera.setVerticalFov(0.6);
    CHECK(camera.verticalFovRadians() == Approx(0.6));
}

TEST_CASE("CoC formula: zero at focus, sign by side, thin-lens magnitude", "[renderer][camera]") {
    ref::Camera camera;
    camera.width = 1000;
    camera.height = 500;
    camera.focalLength = 0.05;
    camera.sensorWidth = 0.036;
    camera.focusDistance = 4.0;
    camera.setFstop(2.0);
    CHECK(camera.apertureRadius == Approx(0.0125));
    CHECK(camera.cocRadiusPixels(4.0) == Approx(0.0).margin(1e-12));
    CHECK(camera.cocRadiusPixels(2.0) > 0.0);
    CHECK(camera.cocRadiusPixels(8.0) < 0.0);
    // A f |F - Z| / (Z (F - f)) * width / sensorWidth at Z = 8: 0.0125 * 0.05 * 4 / (8 * 3.95) / 0.036 * 1000.
    CHECK(camera.cocRadiusPixels(8.0) == Approx(-0.0125 * 0.05 * 4.0 / (8.0 * 3.95) / 0.036 * 1000.0));
}
