// The command line's lens and depth model: the affine CoC the effect evaluates must equal the
// thin-lens formula for every depth kind, and every impossible value is refused with its own message.
#include "cli_error.h"
#include "commands.h"
#include "inputs.h"
#include "lens.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace ffxdof::cli;

namespace {

ThinLens lens50mm() {
    LensSettings settings;
    settings.focusMetres = 4.0;
    settings.focalLengthMm = 50.0;
    settings.sensorWidthMm = 36.0;
    settings.fNumber = 1.4;
    return makeThinLens(settings);
}

// The thin-lens radius written out once more, independently of the code under test:
// |A f (F - Z)| / (Z (F - f)) in metres on the sensor, times pixels per metre of sensor, halved.
double expectedRadius(double A, double f, double F, double Z, double sensorWidth, double width) {
    return A * f * (F - Z) / (Z * (F - f)) * (width / sensorWidth) * 0.5;
}

// Checks radius(d) = d * scale + bias against the thin lens over near, focus and far distances.
void checkAffineCocMatchesThinLens(const ThinLens& lens, const DepthProjection& projection, uint32_t width,
                                   double nearest, double farthest) {
    const CocParameters coc = computeCocParameters(lens, projection, width);
    for (double z : {nearest, nearest * 1.5, 1.0, 2.0, 3.9, 4.0, 4.1, 8.0, 30.0, farthest}) {
        if (z < nearest || z > farthest) continue;
        const double d = float(projection.deviceDepth(z));  // the value the GPU will read
        const double affine = d * coc.cocScale + coc.cocBias;
        const double truth = thinLensCocHalfResPixels(lens, z, width);
        INFO("z = " << z << " m, device depth " << d);
        // float scale/bias and float depth: a few ulps of the largest term, plus a tiny absolute slack.
        const double magnitude = std::fabs(d * coc.cocScale) + std::fabs(coc.cocBias);
        CHECK(affine == Approx(truth).margin(1e-5 * magnitude + 1e-4));
    }
}

template <typename Function>
void requireCliError(Function function, ExitCode code, const std::string& fragment) {
    try {
        function();
        FAIL("expected a CliError containing: " << fragment);
    } catch (const CliError& error) {
        CHECK(error.code() == code);
        CHECK_THAT(error.what(), Catch::Contains(fragment));
    }
}

}  // namespace

TEST_CASE("thin-lens radius in half-resolution pixels", "[lens]") {
    const ThinLens lens = lens50mm();
    CHECK(lens.apertureRadius == Approx(0.05 / 2.8));
    CHECK(lens.focalLength == Approx(0.05));
    CHECK(lens.sensorWidth == Approx(0.036));
    // A = 17.857 mm, f = 50 mm, F = 4 m, Z = 1 m: 0.017857 * 0.05 * 3 / (1 * 3.95) = 6.781e-4 m on the
    // sensor; 1920 px / 36 mm = 53333 px per metre; half resolution: 18.08 px.
    CHECK(thinLensCocHalfResPixels(lens, 1.0, 1920) == Approx(18.0832).epsilon(1e-4));
    CHECK(thinLensCocHalfResPixels(lens, 4.0, 1920) == Approx(0.0).margin(1e-12));
    CHECK(thinLensCocHalfResPixels(lens, 100.0, 1920) < 0.0);  // far field is negative
    CHECK(thinLensCocHalfResPixels(lens, 7.0, 1920) == Approx(expectedRadius(0.05 / 2.8, 0.05, 4.0, 7.0, 0.036, 1920)));
}

TEST_CASE("linear depth: uploaded as a reversed infinite projection", "[lens]") {
    const DepthProjection projection = projectionForLinearDepth(0.5);
    CHECK(projection.reversed);
    CHECK(projection.deviceDepth(0.5) == Approx(1.0));
    CHECK(projection.deviceDepth(1000.0) == Approx(0.0005));
    CHECK(projection.viewDistance(projection.deviceDepth(7.0)) == Approx(7.0));
    checkAffineCocMatchesThinLens(lens50mm(), projection, 1920, 0.5, 1e6);
}

TEST_CASE("device depth from near and far planes", "[lens]") {
    for (bool reversed : {false, true}) {
        INFO("reversed = " << reversed);
        const DepthProjection finite = projectionFromNearFar(0.1, 500.0, reversed);
        CHECK(finite.reversed == reversed);
        CHECK(finite.deviceDepth(0.1) == Approx(reversed ? 1.0 : 0.0).margin(1e-12));
        CHECK(finite.deviceDepth(500.0) == Approx(reversed ? 0.0 : 1.0).margin(1e-12));
        checkAffineCocMatchesThinLens(lens50mm(), finite, 1280, 0.1, 500.0);

        const DepthProjection infinite = projectionFromNearFar(0.1, INFINITY, reversed);
        CHECK(infinite.deviceDepth(0.1) == Approx(reversed ? 1.0 : 0.0).margin(1e-12));
        CHECK(infinite.deviceDepth(1e12) == Approx(reversed ? 0.0 : 1.0).margin(1e-9));
        checkAffineCocMatchesThinLens(lens50mm(), infinite, 1280, 0.1, 1000.0);
    }
}

TEST_CASE("device depth from a projection matrix", "[lens]") {
    const double n = 0.2, f = 200.0;
    SECTION("left-handed, standard (camera looks down +z)") {
        const std::array<double, 16> m = {1.5, 0, 0, 0, 0, 2.0, 0, 0, 0, 0, f / (f - n), -n * f / (f - n), 0, 0, 1, 0};
        const DepthProjection projection = projectionFromMatrix(m, false);
        CHECK_FALSE(projection.reversed);
        CHECK(projection.deviceDepth(n) == Approx(0.0).margin(1e-12));
        checkAffineCocMatchesThinLens(lens50mm(), projection, 1920, n, f);
    }
    SECTION("right-handed, reversed (camera looks down -z), off-centre") {
        // clipZ = n / (f - n) * z + n f / (f - n), clipW = -z: device 1 at distance n, 0 at f.
        const std::array<double, 16> m = {1.5, 0, 0.1, 0, 0, 2.0, -0.2, 0, 0, 0, n / (f - n), n * f / (f - n),
                                          0,   0, -1,  0};
        const DepthProjection projection = projectionFromMatrix(m, true);
        CHECK(projection.reversed);
        CHECK(projection.deviceDepth(n) == Approx(1.0));
        CHECK(projection.deviceDepth(f) == Approx(0.0).margin(1e-12));
        checkAffineCocMatchesThinLens(lens50mm(), projection, 1920, n, f);
    }
    SECTION("refusals") {
        std::array<double, 16> orthographic = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0.01, 0, 0, 0, 0, 1};
        requireCliError([&] { projectionFromMatrix(orthographic, false); }, ExitCode::InvalidValue,
                        "not a perspective projection");
        std::array<double, 16> standard = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1.001, -0.1, 0, 0, 1, 0};
        requireCliError([&] { projectionFromMatrix(standard, true); }, ExitCode::InvalidValue, "--reverse-depth");
        standard[5] = std::numeric_limits<double>::quiet_NaN();
        requireCliError([&] { projectionFromMatrix(standard, false); }, ExitCode::InvalidValue, "finite");
    }
}

TEST_CASE("impossible lens values are refused", "[lens]") {
    LensSettings good;
    good.focusMetres = 2.0;
    good.fNumber = 2.0;
    CHECK_NOTHROW(makeThinLens(good));

    struct Case {
        const char* name;
        void (*change)(LensSettings&);
        ExitCode code;
        const char* fragment;
    };
    const Case cases[] = {
        {"focus at the focal length", [](LensSettings& s) { s.focusMetres = 0.05; }, ExitCode::InvalidValue,
         "must be greater than --focal-length"},
        {"focus inside the focal length", [](LensSettings& s) { s.focusMetres = 0.01; }, ExitCode::InvalidValue,
         "must be greater than --focal-length"},
        {"negative focus", [](LensSettings& s) { s.focusMetres = -3.0; }, ExitCode::InvalidValue, "--focus"},
        {"NaN focus", [](LensSettings& s) { s.focusMetres = std::numeric_limits<double>::quiet_NaN(); },
         ExitCode::InvalidValue, "--focus"},
        {"zero f-number", [](LensSettings& s) { s.fNumber = 0.0; }, ExitCode::InvalidValue, "--fstop"},
        {"negative f-number", [](LensSettings& s) { s.fNumber = -2.0; }, ExitCode::InvalidValue, "--fstop"},
        {"zero focal length", [](LensSettings& s) { s.focalLengthMm = 0.0; }, ExitCode::InvalidValue, "--focal-length"},
        {"infinite sensor", [](LensSettings& s) { s.sensorWidthMm = INFINITY; }, ExitCode::InvalidValue,
         "--sensor-width"},
        {"negative aperture",
         [](LensSettings& s) {
             s.fNumber.reset();
             s.apertureRadiusMetres = -0.01;
         },
         ExitCode::InvalidValue, "--aperture-radius"},
        {"both apertures", [](LensSettings& s) { s.apertureRadiusMetres = 0.01; }, ExitCode::Usage, "not both"},
        {"no aperture", [](LensSettings& s) { s.fNumber.reset(); }, ExitCode::Usage, "--fstop or --aperture-radius"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        LensSettings settings = good;
        c.change(settings);
        requireCliError([&] { makeThinLens(settings); }, c.code, c.fragment);
    }
}

TEST_CASE("near and far planes are checked", "[lens]") {
    requireCliError([] { projectionFromNearFar(0.0, 10.0, false); }, ExitCode::InvalidValue, "--near");
    requireCliError([] { projectionFromNearFar(1.0, 1.0, false); }, ExitCode::InvalidValue, "--far");
    requireCliError([] { projectionFromNearFar(1.0, std::nan(""), true); }, ExitCode::InvalidValue, "--far");
}

TEST_CASE("depth images: bad values are counted and located", "[inputs]") {
    ffxdof::io::ImageR depth(5, 4);
    std::fill(depth.pixels.begin(), depth.pixels.end(), 3.0f);
    CHECK(checkLinearDepth(depth, "d.exr") == Approx(3.0));

    depth.at(3, 2) = std::numeric_limits<float>::quiet_NaN();
    depth.at(4, 3) = INFINITY;
    requireCliError([&] { checkLinearDepth(depth, "d.exr"); }, ExitCode::InvalidValue,
                    "d.exr: 2 values are not finite in the depth (first at x=3, y=2: nan)");

    depth.at(3, 2) = 3.0f;
    depth.at(4, 3) = 3.0f;
    depth.at(1, 0) = 0.0f;
    requireCliError(
        [&] { checkLinearDepth(depth, "d.exr"); }, ExitCode::InvalidValue,
        "1 value is 0 or negative in the linear depth (first at x=1, y=0: 0); linear depth is the view distance");
    requireCliError([&] { checkDeviceDepth(depth, "d.exr"); }, ExitCode::InvalidValue,
                    "19 values are outside [0, 1] in the device depth (first at x=0, y=0: 3); use --depth-kind linear");
}

TEST_CASE("linear depth is converted into 0 < d <= 1", "[inputs]") {
    ffxdof::io::ImageR depth(3, 1);
    depth.pixels = {2.0f, 0.5f, 1e9f};
    const EffectDepth converted = linearToEffectDepth(depth, "d.exr");
    CHECK(converted.projection.reversed);
    CHECK(converted.deviceDepth[0] == Approx(0.25f));
    CHECK(converted.deviceDepth[1] == 1.0f);
    CHECK(converted.deviceDepth[2] == Approx(5e-10f));
}

TEST_CASE("color and depth must match in size and color must be finite", "[inputs]") {
    ffxdof::io::ImageRGBA color(8, 6);
    ffxdof::io::ImageR depth(8, 5);
    requireCliError([&] { checkResolutions(color, "c.exr", depth, "d.exr"); }, ExitCode::InvalidValue,
                    "color and depth differ in size: c.exr is 8x6, d.exr is 8x5");
    depth = ffxdof::io::ImageR(8, 6);
    CHECK_NOTHROW(checkResolutions(color, "c.exr", depth, "d.exr"));
    color.at(2, 1)[1] = -INFINITY;
    requireCliError([&] { checkColorFinite(color, "c.exr"); }, ExitCode::InvalidValue,
                    "1 value is not finite in the color (first at x=2, y=1: -inf)");
}

TEST_CASE("effect options are checked", "[inputs]") {
    EffectOptions options;
    CHECK_NOTHROW(checkEffectOptions(options));
    options.quality = 0;
    requireCliError([&] { checkEffectOptions(options); }, ExitCode::InvalidValue, "--quality must be 1 to 32");
    options.quality = 33;
    requireCliError([&] { checkEffectOptions(options); }, ExitCode::InvalidValue, "got 33");
    options.quality = 10;
    options.cocLimit = std::numeric_limits<double>::quiet_NaN();
    requireCliError([&] { checkEffectOptions(options); }, ExitCode::InvalidValue, "--coc-limit");
    options.cocLimit = -0.5;
    requireCliError([&] { checkEffectOptions(options); }, ExitCode::InvalidValue, "--coc-limit");
}

TEST_CASE("EXR output type: auto keeps values beyond half's range, half refuses them, non-finite is never written") {
    using ffxdof::io::ExrPixelType;
    ffxdof::io::ImageRGBA image(4, 2);
    std::fill(image.pixels.begin(), image.pixels.end(), 1.0f);
    CHECK(chooseExrPixelType("auto", image, "o.exr") == ExrPixelType::Half);
    CHECK(chooseExrPixelType("half", image, "o.exr") == ExrPixelType::Half);
    CHECK(chooseExrPixelType("float", image, "o.exr") == ExrPixelType::Float);
    image.at(1, 1)[2] = 65504.0f;  // half's largest finite value still fits
    CHECK(chooseExrPixelType("auto", image, "o.exr") == ExrPixelType::Half);
    image.at(1, 1)[2] = -70000.0f;
    CHECK(chooseExrPixelType("auto", image, "o.exr") == ExrPixelType::Float);
    CHECK(chooseExrPixelType("float", image, "o.exr") == ExrPixelType::Float);
    requireCliError([&] { chooseExrPixelType("half", image, "o.exr"); }, ExitCode::InvalidValue, "--out-type half");
    image.at(0, 0)[0] = NAN;
    requireCliError([&] { chooseExrPixelType("auto", image, "o.exr"); }, ExitCode::Device, "non-finite");
}

TEST_CASE("autofocus: the point's syntax and the ranges of the point and the region", "[lens][autofocus]") {
    for (const char* good : {"0.5,0.5", "0,1", "1e-1,.5", "nan,0", "+0.25,1.0"}) {
        INFO(good);
        CHECK(autofocusPointSyntaxError(good).empty());
    }
    for (const char* bad : {"0.5", "a,b", "", ",", "0.5,0.5,1", "0.5,", ",0.5", "0.5 0.5", " 0.5,0.5", "0.5, 0.5",
                            "0.5,0.5 ", "0.5;0.5"}) {
        INFO("'" << bad << "'");
        CHECK_THAT(autofocusPointSyntaxError(bad), Catch::Contains("expected X,Y"));
        requireCliError([&] { parseAutofocusPoint(bad); }, ExitCode::Usage, "--autofocus");
    }
    const AutofocusRegion region = parseAutofocusPoint("0.25,0.75", 0.2);
    CHECK(region.x == 0.25);
    CHECK(region.y == 0.75);
    CHECK(region.size == 0.2);
    CHECK(parseAutofocusPoint("0.5,0.5").size == kDefaultFocusRegion);

    CHECK_NOTHROW(checkAutofocusRegion({0.0, 1.0, 1.0}));
    CHECK_NOTHROW(checkAutofocusRegion({1.0, 0.0, 1e-6}));
    for (const AutofocusRegion& bad : {AutofocusRegion{1.01, 0.5, 0.1}, AutofocusRegion{0.5, -0.01, 0.1},
                                       AutofocusRegion{NAN, 0.5, 0.1}, AutofocusRegion{0.5, INFINITY, 0.1}}) {
        requireCliError([&] { checkAutofocusRegion(bad); }, ExitCode::InvalidValue,
                        "--autofocus X,Y must lie in 0 to 1");
    }
    for (const double size : {0.0, -0.1, 1.01, double(NAN), double(INFINITY)}) {
        INFO(size);
        requireCliError([&] { checkAutofocusRegion({0.5, 0.5, size}); }, ExitCode::InvalidValue, "--focus-region");
    }
}

TEST_CASE("autofocus: a lens without focus and the range of distances", "[lens][autofocus]") {
    LensSettings settings;
    settings.focalLengthMm = 50.0;
    settings.fNumber = 2.0;
    const ThinLens lens = makeThinLens(settings, /*autofocus=*/true);  // no --focus needed
    CHECK(lens.focusDistance == 0.0);
    CHECK(lens.apertureRadius == Approx(0.0125));
    requireCliError([&] { makeThinLens(settings); }, ExitCode::InvalidValue, "--focus");

    // From twice the focal length to the far plane, or 10 km where there is none (or it is farther).
    const FocusRange linear = autofocusRange(lens, projectionForLinearDepth(0.5));
    CHECK(linear.nearest == Approx(0.1));
    CHECK(linear.farthest == kAutofocusFarthest);
    for (const bool reversed : {false, true}) {
        INFO("reversed = " << reversed);
        CHECK(autofocusRange(lens, projectionFromNearFar(0.1, 500.0, reversed)).farthest == Approx(500.0));
        CHECK(autofocusRange(lens, projectionFromNearFar(0.1, INFINITY, reversed)).farthest == kAutofocusFarthest);
        CHECK(autofocusRange(lens, projectionFromNearFar(0.1, 2e4, reversed)).farthest == kAutofocusFarthest);
    }
    const double n = 0.2, f = 200.0;
    const std::array<double, 16> rightHanded = {1.5, 0, 0,  0, 0, 2.0, 0, 0, 0, 0, n / (f - n), n * f / (f - n),
                                                0,   0, -1, 0};
    CHECK(autofocusRange(lens, projectionFromMatrix(rightHanded, true)).farthest == Approx(f));
    requireCliError([&] { autofocusRange(lens, projectionFromNearFar(0.01, 0.08, false)); }, ExitCode::InvalidValue,
                    "twice --focal-length");
}

TEST_CASE("autofocus: the dispatch's lens and projection terms are those of manual focus", "[lens][autofocus]") {
    LensSettings settings;
    settings.focalLengthMm = 35.0;
    settings.sensorWidthMm = 24.0;
    settings.fNumber = 1.8;
    const ThinLens lens = makeThinLens(settings, true);
    const double n = 0.2, f = 200.0;
    const std::array<double, 16> rightHanded = {1.5, 0, 0,  0, 0, 2.0, 0, 0, 0, 0, n / (f - n), n * f / (f - n),
                                                0,   0, -1, 0};
    for (const DepthProjection& projection : {projectionForLinearDepth(0.7), projectionFromNearFar(0.1, 500.0, false),
                                              projectionFromMatrix(rightHanded, true)}) {
        const FocusRange range = autofocusRange(lens, projection);
        const FfxDofAutofocus a = makeAutofocus(lens, projection, 1920, {0.25, 0.75, 0.2}, range);
        CHECK(a.regionCenter[0] == 0.25f);
        CHECK(a.regionCenter[1] == 0.75f);
        CHECK(a.regionSize[0] == 0.2f);
        CHECK(a.regionSize[1] == 0.2f);
        CHECK(a.minFocusDistance == float(range.nearest));
        CHECK(a.maxFocusDistance == float(range.farthest));
        CHECK(a.timeConstant == 0.0f);
        // The SDK's CoC line from these terms at a focus F is the one --focus F gives, bit for bit.
        for (const double focus : {0.5, 3.0, 40.0}) {
            ThinLens focused = lens;
            focused.focusDistance = focus;
            const CocParameters manual = computeCocParameters(focused, projection, 1920);
            const float signedFocus = float(a.proj43 < 0.0f ? -focus : focus);
            CHECK(ffxDofCalculateCocScale(a.aperture, signedFocus, a.focalLength, a.conversion, a.proj33, a.proj34,
                                          a.proj43) == manual.cocScale);
            CHECK(ffxDofCalculateCocBias(a.aperture, signedFocus, a.focalLength, a.conversion, a.proj33, a.proj34,
                                         a.proj43) == manual.cocBias);
        }
    }
}

TEST_CASE("autofocus: the distances it can reach are those of the pixels it reads", "[lens][autofocus]") {
    // 40x20 linear depth: a target of 2 m at x 10..19, y 5..14, a wall at 30 m elsewhere.
    const uint32_t width = 40, height = 20;
    ffxdof::io::ImageR depth(width, height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) depth.at(x, y) = (x >= 10 && x < 20 && y >= 5 && y < 15) ? 2.0f : 30.0f;
    }
    const EffectDepth effect = linearToEffectDepth(depth, "d.exr");
    const FocusRange range{0.1, kAutofocusFarthest};
    const auto reach = [&](double x, double y, double size, const FocusRange& clamp) {
        return reachableAutofocus(effect.deviceDepth, width, height, effect.projection, {x, y, size}, clamp);
    };
    const FocusRange inside = reach(0.375, 0.5, 0.1, range);  // pixels 13..17 (and a spare one) of the target
    CHECK(inside.nearest == Approx(2.0));
    CHECK(inside.farthest == Approx(2.0));
    const FocusRange straddling = reach(0.5, 0.5, 0.2, range);  // x 16..24: target and wall
    CHECK(straddling.nearest == Approx(2.0));
    CHECK(straddling.farthest == Approx(30.0));
    const FocusRange wall = reach(0.9, 0.5, 0.1, range);
    CHECK(wall.nearest == Approx(30.0));
    CHECK(wall.farthest == Approx(30.0));
    // Next to the target: the centre's 3x3 neighbours (and the spare pixel) reach it.
    CHECK(reach(21.5 / 40.0, 0.5, 0.01, range).nearest == Approx(2.0));
    // Clamped to the range.
    const FocusRange clamped = reach(0.5, 0.5, 1.0, {3.0, 10.0});
    CHECK(clamped.nearest == 3.0);
    CHECK(clamped.farthest == 10.0);
}

TEST_CASE("autofocus: the printed focus has three significant digits", "[lens][autofocus]") {
    CHECK(focusText(2.4801) == "focus: 2.48 m");
    CHECK(focusText(0.8) == "focus: 0.800 m");
    CHECK(focusText(0.01234) == "focus: 0.0123 m");
    CHECK(focusText(12.34) == "focus: 12.3 m");
    CHECK(focusText(250.0) == "focus: 250 m");
    CHECK(focusText(10000.0) == "focus: 10000 m");
}
