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
        &commandListStorage, image(kColor), image(kDepth), image(kOutput), -2.0f, 1.0f, nullptr};

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

TEST_CASE("the version is 1.0.0 packed as FidelityFX packs it") {
    CHECK(ffxDofGetEffectVersion() == ((1u << 22) | (0u << 12) | 0u));
}
