// Every invalid description gets its specific error code, never a crash; valid ones reach the backend.
#include "fake_backend.h"
#include "ffx_dof_context.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <string>

using ffxdof::testing::RecordingBackend;

namespace {

constexpr uint64_t kColor = 0x1000, kDepth = 0x2000, kOutput = 0x3000;

FfxDofResource image(uint64_t handle, uint32_t width = 64, uint32_t height = 32) {
    return FfxDofResource{handle, 0, width, height, 0, 0};
}

struct Fixture {
    Fixture() { description.backendInterface = backend; }
    ~Fixture() {
        ffxDofContextDestroy(&context);
        // The backend may already be gone if a test destroyed it.
        if (backend) REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    }
    RecordingBackend* backend = new RecordingBackend;
    FfxDofContextDescription description{0, 10, {64, 32}, nullptr, 0.05f};
    FfxDofContext context = nullptr;
    int commandListStorage = 0;
    FfxDofDispatchDescription dispatch{
        &commandListStorage, image(kColor), image(kDepth), image(kOutput), -2.0f, 1.0f, nullptr, nullptr};

    FfxDofErrorCode create() { return ffxDofContextCreate(&context, &description); }
};

std::string lastError() { return ffxDofGetLastErrorMessage(); }

}  // namespace

TEST_CASE_METHOD(Fixture, "a valid description creates a context and reaches the backend") {
    REQUIRE(create() == FFX_DOF_OK);
    REQUIRE(context != nullptr);
    REQUIRE(backend->plans.size() == 1);
    CHECK(backend->plans[0].config.quality == 10);
    CHECK(backend->liveContexts == 1);
    REQUIRE(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
    CHECK(backend->dispatches.size() == 1);
    FfxDofMemoryUsage usage{};
    REQUIRE(ffxDofContextGetGpuMemoryUsage(&context, &usage) == FFX_DOF_OK);
    CHECK(usage.totalUsageInBytes == 1234);
    REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
    CHECK(context == nullptr);
    CHECK(backend->liveContexts == 0);
}

TEST_CASE_METHOD(Fixture, "context creation rejects each invalid description with its own code") {
    SECTION("null pContext") { CHECK(ffxDofContextCreate(nullptr, &description) == FFX_DOF_ERROR_INVALID_POINTER); }
    SECTION("null description, and the handle is cleared") {
        context = reinterpret_cast<FfxDofContext>(&commandListStorage);  // garbage the call must overwrite
        CHECK(ffxDofContextCreate(&context, nullptr) == FFX_DOF_ERROR_INVALID_POINTER);
        CHECK(context == nullptr);
    }
    SECTION("unknown flag bits") {
        description.flags = FFX_DOF_REVERSE_DEPTH | (1u << 7);
        CHECK(create() == FFX_DOF_ERROR_INVALID_FLAGS);
        CHECK(lastError().find("0x80") != std::string::npos);
    }
    SECTION("quality 0") {
        description.quality = 0;
        CHECK(create() == FFX_DOF_ERROR_INVALID_QUALITY);
    }
    SECTION("quality above the maximum") {
        description.quality = FFX_DOF_MAX_QUALITY + 1;
        CHECK(create() == FFX_DOF_ERROR_INVALID_QUALITY);
    }
    SECTION("zero width") {
        description.resolution = {0, 32};
        CHECK(create() == FFX_DOF_ERROR_INVALID_RESOLUTION);
    }
    SECTION("zero height") {
        description.resolution = {64, 0};
        CHECK(create() == FFX_DOF_ERROR_INVALID_RESOLUTION);
    }
    SECTION("oversized resolution") {
        description.resolution = {FFX_DOF_MAX_RESOLUTION + 1, 32};
        CHECK(create() == FFX_DOF_ERROR_INVALID_RESOLUTION);
        description.resolution = {64, FFX_DOF_MAX_RESOLUTION + 1};
        CHECK(create() == FFX_DOF_ERROR_INVALID_RESOLUTION);
    }
    SECTION("negative cocLimitFactor") {
        description.cocLimitFactor = -0.01f;
        CHECK(create() == FFX_DOF_ERROR_INVALID_COC_LIMIT);
    }
    SECTION("NaN cocLimitFactor") {
        description.cocLimitFactor = std::numeric_limits<float>::quiet_NaN();
        CHECK(create() == FFX_DOF_ERROR_INVALID_COC_LIMIT);
    }
    SECTION("infinite cocLimitFactor") {
        description.cocLimitFactor = std::numeric_limits<float>::infinity();
        CHECK(create() == FFX_DOF_ERROR_INVALID_COC_LIMIT);
    }
    SECTION("null backend") {
        description.backendInterface = nullptr;
        CHECK(create() == FFX_DOF_ERROR_INVALID_POINTER);
        CHECK(lastError().find("backendInterface") != std::string::npos);
    }
    SECTION("a backend failure is passed through") {
        backend->failCreation = true;
        CHECK(create() == FFX_DOF_ERROR_UNSUPPORTED);
        CHECK(backend->liveContexts == 0);
    }
    CHECK(context == nullptr);
    CHECK(backend->dispatches.empty());
}

TEST_CASE_METHOD(Fixture, "the limits themselves are accepted") {
    description.quality = FFX_DOF_MAX_QUALITY;
    description.resolution = {1, FFX_DOF_MAX_RESOLUTION};
    description.cocLimitFactor = 0.0f;
    description.flags = FFX_DOF_ALL_FLAGS;
    CHECK(create() == FFX_DOF_OK);
}

TEST_CASE_METHOD(Fixture, "dispatch rejects each invalid description with its own code") {
    REQUIRE(create() == FFX_DOF_OK);
    SECTION("null pContext") { CHECK(ffxDofContextDispatch(nullptr, &dispatch) == FFX_DOF_ERROR_INVALID_POINTER); }
    SECTION("null description") { CHECK(ffxDofContextDispatch(&context, nullptr) == FFX_DOF_ERROR_INVALID_POINTER); }
    SECTION("null command list") {
        dispatch.commandList = nullptr;
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_POINTER);
    }
    SECTION("null color") {
        dispatch.color.handle = 0;
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_RESOURCE);
        CHECK(lastError().find("color") != std::string::npos);
    }
    SECTION("null depth") {
        dispatch.depth.handle = 0;
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_RESOURCE);
    }
    SECTION("null output") {
        dispatch.output.handle = 0;
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_RESOURCE);
    }
    SECTION("a resource of another size") {
        dispatch.depth = image(kDepth, 64, 31);
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_RESOURCE);
        CHECK(lastError().find("64x31") != std::string::npos);
    }
    SECTION("output equal to color without FFX_DOF_OUTPUT_PRE_INIT") {
        dispatch.output = dispatch.color;
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_OUTPUT_ALIASES_INPUT);
    }
    SECTION("output equal to depth") {
        dispatch.output = dispatch.depth;
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_RESOURCE);
    }
    SECTION("non-finite CoC scale or bias") {
        dispatch.cocScale = std::numeric_limits<float>::quiet_NaN();
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_ARGUMENT);
        dispatch.cocScale = 1.0f;
        dispatch.cocBias = -std::numeric_limits<float>::infinity();
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_ARGUMENT);
    }
    CHECK(backend->dispatches.empty());
}

TEST_CASE_METHOD(Fixture, "in-place output is accepted with FFX_DOF_OUTPUT_PRE_INIT") {
    description.flags = FFX_DOF_OUTPUT_PRE_INIT;
    REQUIRE(create() == FFX_DOF_OK);
    dispatch.output = dispatch.color;
    REQUIRE(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
    REQUIRE(backend->dispatches.size() == 1);
    CHECK(backend->dispatches[0].outputIsColor);
    CHECK(backend->plans[0].axes.outputPreInit == 1);
}

TEST_CASE_METHOD(Fixture, "a destroyed context is refused everywhere, also through a stale copy of the handle") {
    REQUIRE(create() == FFX_DOF_OK);
    FfxDofContext staleCopy = context;
    REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
    CHECK(context == nullptr);
    CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_CONTEXT);
    CHECK(ffxDofContextDispatch(&staleCopy, &dispatch) == FFX_DOF_ERROR_INVALID_CONTEXT);
    FfxDofMemoryUsage usage{};
    CHECK(ffxDofContextGetGpuMemoryUsage(&staleCopy, &usage) == FFX_DOF_ERROR_INVALID_CONTEXT);
    CHECK(ffxDofContextDestroy(&staleCopy) == FFX_DOF_ERROR_INVALID_CONTEXT);
    CHECK(ffxDofContextDestroy(&context) == FFX_DOF_OK);  // NULL handle: nothing to do
    CHECK(ffxDofContextDestroy(nullptr) == FFX_DOF_ERROR_INVALID_POINTER);
    CHECK(backend->dispatches.empty());
}

TEST_CASE_METHOD(Fixture, "memory usage needs an output pointer") {
    REQUIRE(create() == FFX_DOF_OK);
    CHECK(ffxDofContextGetGpuMemoryUsage(&context, nullptr) == FFX_DOF_ERROR_INVALID_POINTER);
}

TEST_CASE_METHOD(Fixture, "a backend with live contexts is not destroyed") {
    REQUIRE(create() == FFX_DOF_OK);
    CHECK(ffxDofBackendDestroy(backend) == FFX_DOF_ERROR_BACKEND_IN_USE);
    REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
    CHECK(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    backend = nullptr;
    CHECK(ffxDofBackendDestroy(nullptr) == FFX_DOF_OK);
}

TEST_CASE_METHOD(Fixture, "a destroyed or garbage backend is refused without touching its memory") {
    // Destroying twice: the second call must not read the freed object (it once reported a garbage
    // count of live contexts, and under ASan it is a use-after-free).
    REQUIRE(ffxDofBackendDestroy(backend) == FFX_DOF_OK);
    FfxDofBackend destroyed = backend;
    backend = nullptr;
    CHECK(ffxDofBackendDestroy(destroyed) == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK_THAT(lastError(), Catch::Contains("not a live backend"));

    // Creating a context with the destroyed backend, or with a pointer that never was one.
    description.backendInterface = destroyed;
    CHECK(create() == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK(context == nullptr);
    CHECK_THAT(lastError(), Catch::Contains("backendInterface"));
    alignas(16) unsigned char garbage[64];
    std::memset(garbage, 0xA5, sizeof(garbage));
    description.backendInterface = reinterpret_cast<FfxDofBackend>(garbage);
    CHECK(create() == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK(context == nullptr);
    CHECK(ffxDofBackendDestroy(reinterpret_cast<FfxDofBackend>(garbage)) == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK(ffxDofBackendDestroy(reinterpret_cast<FfxDofBackend>(uintptr_t(0x10))) == FFX_DOF_ERROR_INVALID_ARGUMENT);
}

TEST_CASE("every error code has its own description") {
    const FfxDofErrorCode codes[] = {FFX_DOF_OK,
                                     FFX_DOF_ERROR_INVALID_POINTER,
                                     FFX_DOF_ERROR_INVALID_RESOLUTION,
                                     FFX_DOF_ERROR_INVALID_QUALITY,
                                     FFX_DOF_ERROR_INVALID_COC_LIMIT,
                                     FFX_DOF_ERROR_INVALID_FLAGS,
                                     FFX_DOF_ERROR_INVALID_RESOURCE,
                                     FFX_DOF_ERROR_OUTPUT_ALIASES_INPUT,
                                     FFX_DOF_ERROR_INVALID_CONTEXT,
                                     FFX_DOF_ERROR_INVALID_ARGUMENT,
                                     FFX_DOF_ERROR_UNSUPPORTED,
                                     FFX_DOF_ERROR_OUT_OF_MEMORY,
                                     FFX_DOF_ERROR_BACKEND,
                                     FFX_DOF_ERROR_BACKEND_IN_USE};
    std::set<std::string> texts;
    for (FfxDofErrorCode code : codes) texts.insert(ffxDofGetErrorString(code));
    CHECK(texts.size() == std::size(codes));
    CHECK(std::string(ffxDofGetErrorString(static_cast<FfxDofErrorCode>(-999))) == "unknown error code");
}

TEST_CASE("the version is 2.1.0 packed as FidelityFX packs it") {
    CHECK(ffxDofGetEffectVersion() == ((2u << 22) | (1u << 12) | 0u));
}

namespace {

FfxDofAutofocus validAutofocus() {
    FfxDofAutofocus a{};
    a.regionCenter[0] = a.regionCenter[1] = 0.5f;
    a.regionSize[0] = a.regionSize[1] = 0.1f;
    a.aperture = 0.0125f;
    a.focalLength = 0.05f;
    a.conversion = 900.0f;
    a.proj33 = -1.001f;
    a.proj34 = -0.1001f;
    a.proj43 = -1.0f;
    a.minFocusDistance = 0.2f;
    a.maxFocusDistance = 100.0f;
    a.timeConstant = 0.5f;
    a.deltaTime = 1.0f / 60.0f;
    return a;
}

}  // namespace

TEST_CASE_METHOD(Fixture, "an autofocus dispatch plans the autofocus pass and its constants") {
    REQUIRE(create() == FFX_DOF_OK);
    REQUIRE(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);  // manual: no autofocus pass
    const FfxDofAutofocus autofocus = validAutofocus();
    dispatch.pAutofocus = &autofocus;
    dispatch.cocScale = std::numeric_limits<float>::quiet_NaN();  // ignored with autofocus
    REQUIRE(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
    REQUIRE(ffxDofContextResetAutofocus(&context) == FFX_DOF_OK);
    REQUIRE(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
    REQUIRE(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
    REQUIRE(backend->dispatches.size() == 4);

    const uint32_t autofocusPass = uint32_t(ffxdof::Pass::Autofocus);
    CHECK_FALSE(backend->dispatches[0].runs[autofocusPass]);
    CHECK(backend->dispatches[0].constants.focusFlags == 0);
    for (uint32_t p = 0; p < ffxdof::kPassCount; ++p) CHECK(backend->dispatches[1].runs[p]);
    const FfxDofConstants& c = backend->dispatches[1].constants;
    CHECK(c.focusFlags == FFX_DOF_FOCUS_FLAG_AUTO);
    CHECK(c.focusInvZScale == Approx(-1.0f / -0.1001f));
    CHECK(c.focusInvZBias == Approx(-1.001f / -0.1001f));
    CHECK(c.focusMinDistance == Approx(-0.2f));  // signed like view z: this camera looks down -Z
    CHECK(c.focusMaxDistance == Approx(-100.0f));
    CHECK(c.focusBlend == Approx(1.0 - std::exp(-(1.0 / 60.0) / 0.5)));
    CHECK(c.focusLensFactor == Approx(0.0125f * 0.05f * 900.0f));
    // The reset applies to the next autofocus dispatch only.
    CHECK(backend->dispatches[2].constants.focusFlags == (FFX_DOF_FOCUS_FLAG_AUTO | FFX_DOF_FOCUS_FLAG_RESET));
    CHECK(backend->dispatches[3].constants.focusFlags == FFX_DOF_FOCUS_FLAG_AUTO);
    // No smoothing with a zero time constant.
    FfxDofAutofocus immediate = autofocus;
    immediate.timeConstant = 0.0f;
    dispatch.pAutofocus = &immediate;
    REQUIRE(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
    CHECK(backend->dispatches.back().constants.focusBlend == 1.0f);
}

TEST_CASE_METHOD(Fixture, "each invalid autofocus field is refused by name") {
    REQUIRE(create() == FFX_DOF_OK);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const struct {
        const char* field;
        void (*spoil)(FfxDofAutofocus&, float);
    } cases[] = {
        {"regionCenter[0]", [](FfxDofAutofocus& a, float) { a.regionCenter[0] = 1.5f; }},
        {"regionCenter[1]", [](FfxDofAutofocus& a, float n) { a.regionCenter[1] = n; }},
        {"regionSize[0]", [](FfxDofAutofocus& a, float) { a.regionSize[0] = 0.0f; }},
        {"regionSize[1]", [](FfxDofAutofocus& a, float) { a.regionSize[1] = 2.0f; }},
        {"aperture", [](FfxDofAutofocus& a, float) { a.aperture = -1.0f; }},
        {"focalLength", [](FfxDofAutofocus& a, float) { a.focalLength = 0.0f; }},
        {"conversion", [](FfxDofAutofocus& a, float n) { a.conversion = n; }},
        {"proj34", [](FfxDofAutofocus& a, float) { a.proj34 = 0.0f; }},
        {"minFocusDistance", [](FfxDofAutofocus& a, float) { a.minFocusDistance = 0.01f; }},
        {"maxFocusDistance", [](FfxDofAutofocus& a, float) { a.maxFocusDistance = 0.1f; }},
        {"maxFocusDistance", [](FfxDofAutofocus& a, float) { a.maxFocusDistance = INFINITY; }},
        {"timeConstant", [](FfxDofAutofocus& a, float) { a.timeConstant = -1.0f; }},
        {"deltaTime", [](FfxDofAutofocus& a, float n) { a.deltaTime = n; }},
    };
    for (const auto& c : cases) {
        FfxDofAutofocus autofocus = validAutofocus();
        c.spoil(autofocus, nan);
        dispatch.pAutofocus = &autofocus;
        INFO(c.field);
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_ARGUMENT);
        CHECK(lastError().find(c.field) != std::string::npos);
    }
    CHECK(backend->dispatches.empty());
    CHECK(ffxDofContextResetAutofocus(nullptr) == FFX_DOF_ERROR_INVALID_POINTER);
    float distance = 0.0f;
    CHECK(ffxDofContextGetAutofocusDistance(&context, 0, nullptr) == FFX_DOF_ERROR_INVALID_POINTER);
    CHECK(ffxDofContextGetAutofocusDistance(&context, 0, &distance) == FFX_DOF_ERROR_INVALID_ARGUMENT);
}

TEST_CASE_METHOD(Fixture, "each invalid aperture field is refused by name") {
    REQUIRE(create() == FFX_DOF_OK);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const struct {
        const char* field;
        FfxDofAperture aperture;
    } cases[] = {
        {"bladeCount", {1, 0.0f, 0.0f, 1.0f, 0.0f}},        {"bladeCount", {2, 0.0f, 0.0f, 1.0f, 0.0f}},
        {"bladeCount", {17, 0.0f, 0.0f, 1.0f, 0.0f}},       {"bladeRotation", {6, nan, 0.0f, 1.0f, 0.0f}},
        {"bladeRotation", {6, INFINITY, 0.0f, 1.0f, 0.0f}}, {"roundness", {6, 0.0f, -0.1f, 1.0f, 0.0f}},
        {"roundness", {6, 0.0f, 1.5f, 1.0f, 0.0f}},         {"anamorphicRatio", {0, 0.0f, 0.0f, 0.49f, 0.0f}},
        {"anamorphicRatio", {0, 0.0f, 0.0f, 2.01f, 0.0f}},  {"anamorphicRatio", {0, 0.0f, 0.0f, 0.0f, 0.0f}},
        {"catEye", {0, 0.0f, 0.0f, 1.0f, -0.5f}},           {"catEye", {0, 0.0f, 0.0f, 1.0f, nan}},
    };
    for (const auto& c : cases) {
        dispatch.pAperture = &c.aperture;
        INFO(c.field);
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_ARGUMENT);
        CHECK(lastError().find(c.field) != std::string::npos);
    }
    CHECK(backend->dispatches.empty());
    // A shaped aperture needs a context made for shapes; the round one, given any way, does not.
    const FfxDofAperture hexagon{6, 0.0f, 0.0f, 1.0f, 0.0f};
    dispatch.pAperture = &hexagon;
    CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_ERROR_INVALID_ARGUMENT);
    CHECK(lastError().find("FFX_DOF_ENABLE_APERTURE_SHAPES") != std::string::npos);
    for (const FfxDofAperture& round :
         {FfxDofAperture{0, 1.0f, 0.5f, 1.0f, 0.0f}, FfxDofAperture{6, 1.0f, 1.0f, 1.0f, 0.0f}}) {
        dispatch.pAperture = &round;
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
    }
    REQUIRE(ffxDofContextDestroy(&context) == FFX_DOF_OK);
    description.flags = FFX_DOF_ENABLE_APERTURE_SHAPES;
    REQUIRE(create() == FFX_DOF_OK);
    // The limits themselves are accepted.
    for (const FfxDofAperture& aperture :
         {FfxDofAperture{3, -7.0f, 0.0f, 0.5f, 0.0f}, FfxDofAperture{16, 100.0f, 1.0f, 2.0f, 1.0f},
          FfxDofAperture{0, 0.0f, 0.0f, 1.0f, 0.0f}}) {
        dispatch.pAperture = &aperture;
        CHECK(ffxDofContextDispatch(&context, &dispatch) == FFX_DOF_OK);
    }
}
