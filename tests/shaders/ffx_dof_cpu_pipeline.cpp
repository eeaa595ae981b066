// The CPU implementation of the accessors of every pass, and the workgroup runner.
#include "ffx_dof_cpu_pipeline.h"

#include "ffx_dof_downsample_depth.h"
#include "ffx_dof_downsample_color.h"
#include "ffx_dof_dilate.h"
#include "ffx_dof_blur.h"
#include "ffx_dof_composite.h"
#include "ffx_dof_plan.h"

#include <ucontext.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <memory>
#include <stdexcept>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#endif

namespace {

template <typename T>
struct Image {
    uint32_t width = 0, height = 0;
    std::vector<T> texels;
    void resize(uint32_t w, uint32_t h) {
        width = w;
        height = h;
        texels.assign(size_t(w) * h, T(0));
    }
    // Reads out of range are an error in the shaders' logic: they must clamp first.
    const T& at(int32_t x, int32_t y) const {
        if (x < 0 || y < 0 || uint32_t(x) >= width || uint32_t(y) >= height) throw std::out_of_range("image read");
        return texels[size_t(y) * width + uint32_t(x)];
    }
    void store(uint32_t x, uint32_t y, const T& value) {
        if (x >= width || y >= height) throw std::out_of_range("image write");
        texels[size_t(y) * width + x] = value;
    }
};

// TILE_LISTS words nothing has written (no packed tile: tile coordinates stay far below 0xbeef).
constexpr uint32_t kUnwrittenListWord = 0xdeadbeefu;
// HIGHLIGHTS words before pass 2 writes them: garbage, as on a GPU (no initial value), never an empty slot
// of zeros that would hide a composite reading a slot pass 2 did not write.
constexpr uint32_t kUnwrittenHighlightWord = 0xdeadbeefu;

struct State {
    FfxDofConstants constants{};
    const ffxdoftest::Scene* scene = nullptr;
    Image<glm::vec3> halfColor;
    Image<float> halfCoc;
    Image<glm::uvec2> coarseMips[FFX_DOF_OPTION_MAX_MIP];  // COARSE_MIPS, by MIP of the half-res chain (0 unused)
    Image<glm::vec2> tiles, layerAlpha;
    Image<glm::vec4> dilatedTiles;
    Image<glm::vec3> nearColor, farColor;
    Image<glm::vec4> output;
    std::atomic<uint32_t> globals[FFX_DOF_GLOBALS_WORD_COUNT] = {};
    // TILE_LIST_ARGS (garbage until pass 1 resets it, as on a GPU) and TILE_LISTS.
    std::atomic<uint32_t> tileListArgs[ffxdof::kTileListArgsWordCount];
    std::vector<uint32_t> tileLists;
    std::vector<uint32_t> highlights;  // HIGHLIGHTS
    // Per word of HIGHLIGHTS, whether pass 2 wrote it: any value is a valid highlight word, so only this
    // tells a read of garbage (bytes, not bits: invocations write neighbouring words concurrently).
    std::vector<uint8_t> highlightWritten;
    State() {
        for (std::atomic<uint32_t>& word : tileListArgs) word.store(0xdeadbeefu);
    }
};
State* g_state = nullptr;

// The 64 invocations of a workgroup as fibers (ucontext) on the calling thread. Each runs until it reaches the
// group barrier or returns, then the next one runs; once all of them wait at the barrier they go on, in turn.
// They were 64 threads with a mutex and a condition variable per barrier: on a 2-core machine four fifths of
// the CPU tests' time went to the kernel switching them (one test: 12.7 s, 9.9 s of it in the kernel, a
// million switches). Fibers are deterministic, and an invocation that returns while others wait at a barrier
// (undefined on a GPU; threads would hang) ends the run with a message. Like a thread of its own, an
// invocation that throws ends the process.
class InvocationFibers {
public:
    using Pass = std::function<void(FfxUInt32x2, FfxUInt32)>;

    InvocationFibers() {
        for (Fiber& fiber : fibers_) fiber.stack.reset(new char[kStackBytes]);
    }

    // Runs `pass` for every invocation of group `group` and returns once all of them have.
    void runGroup(FfxUInt32x2 group, const Pass& pass) {
        group_ = group;
        pass_ = &pass;
        for (Fiber& fiber : fibers_) {
            getcontext(&fiber.context);
            fiber.context.uc_stack.ss_sp = fiber.stack.get();
            fiber.context.uc_stack.ss_size = kStackBytes;
            fiber.context.uc_link = nullptr;  // an invocation never returns from entry(): it switches back
            makecontext(&fiber.context, &InvocationFibers::entry, 0);
            fiber.finished = false;
        }
        running_ = this;
        for (uint32_t round = 0;; ++round) {
            uint32_t finished = 0;
            for (current_ = 0; current_ < FFX_DOF_GROUP_THREADS; ++current_) {
                Fiber& fiber = fibers_[current_];
                if (!fiber.finished) switchToInvocation(fiber);
                finished += fiber.finished ? 1 : 0;
            }
            if (finished == FFX_DOF_GROUP_THREADS) break;
            if (finished != 0) {
                std::fprintf(stderr,
                             "CPU pipeline: group (%u, %u): %u of %u invocations returned while the others wait at "
                             "barrier %u (barriers must be in uniform control flow)\n",
                             group.x, group.y, finished, unsigned(FFX_DOF_GROUP_THREADS), round);
                std::abort();
            }
        }
        running_ = nullptr;
    }

    // The group barrier, called by the invocation that runs.
    static void barrier() { running_->switchToScheduler(false); }

private:
    // The deepest invocation used 10 KB in the Debug build under AddressSanitizer (the CPU tests of every pass).
    // Small, since AddressSanitizer's swapcontext clears the shadow of the whole stack at every switch: 1 MB
    // stacks made that an mmap per switch and most of the sanitizer run's time.
    static constexpr size_t kStackBytes = size_t(128) << 10;
    struct Fiber {
        ucontext_t context{};
        std::unique_ptr<char[]> stack;
        bool finished = false;
    };

    static void entry() {
        InvocationFibers& self = *running_;
        self.arrivedOnFiber();
        try {
            (*self.pass_)(self.group_, self.current_);
        } catch (...) {
            std::terminate();  // prints the exception, as for a thread
        }
        self.fibers_[self.current_].finished = true;
        self.switchToScheduler(true);
    }

    void switchToInvocation(Fiber& fiber) {
#if defined(__SANITIZE_ADDRESS__)
        void* fakeStack = nullptr;
        __sanitizer_start_switch_fiber(&fakeStack, fiber.stack.get(), kStackBytes);
#endif
        swapcontext(&scheduler_, &fiber.context);
#if defined(__SANITIZE_ADDRESS__)
        __sanitizer_finish_switch_fiber(fakeStack, nullptr, nullptr);
#endif
    }
    void switchToScheduler(bool finished) {
#if defined(__SANITIZE_ADDRESS__)
        void* fakeStack = nullptr;
        __sanitizer_start_switch_fiber(finished ? nullptr : &fakeStack, schedulerStackBottom_, schedulerStackSize_);
#endif
        (void)finished;
        swapcontext(&fibers_[current_].context, &scheduler_);
#if defined(__SANITIZE_ADDRESS__)
        __sanitizer_finish_switch_fiber(fakeStack, &schedulerStackBottom_, &schedulerStackSize_);
#endif
    }
    // AddressSanitizer learns the scheduler's stack from the first switch onto a fiber.
    void arrivedOnFiber() {
#if defined(__SANITIZE_ADDRESS__)
        __sanitizer_finish_switch_fiber(nullptr, &schedulerStackBottom_, &schedulerStackSize_);
#endif
    }

    static inline InvocationFibers* running_ = nullptr;  // the runner whose group runs (one test thread)
    std::array<Fiber, FFX_DOF_GROUP_THREADS> fibers_;
    ucontext_t scheduler_{};
    FfxUInt32x2 group_{0u, 0u};
    const Pass* pass_ = nullptr;
    uint32_t current_ = 0;
    const void* schedulerStackBottom_ = nullptr;
    size_t schedulerStackSize_ = 0;
};

void runGroups(uint32_t groupsX, uint32_t groupsY, const InvocationFibers::Pass& pass) {
    static InvocationFibers fibers;
    for (uint32_t y = 0; y < groupsY; ++y) {
        for (uint32_t x = 0; x < groupsX; ++x) fibers.runGroup(FfxUInt32x2(x, y), pass);
    }
}

uint32_t ceilDiv(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

}  // namespace

// ---- Accessors -----------------------------------------------------------------------------------
void ffxDofCpuGroupBarrier() { InvocationFibers::barrier(); }
FfxDofConstants ffxDofGetConstants() { return g_state->constants; }
FfxFloat32 ffxDofLoadInputDepth(FfxUInt32x2 p) {
    if (p.x >= g_state->scene->width || p.y >= g_state->scene->height) throw std::out_of_range("depth read");
    return g_state->scene->depth[size_t(p.y) * g_state->scene->width + p.x];
}
FfxFloat32x4 ffxDofLoadInputColor(FfxUInt32x2 p) {
    if (p.x >= g_state->scene->width || p.y >= g_state->scene->height) throw std::out_of_range("color read");
    return g_state->scene->color[size_t(p.y) * g_state->scene->width + p.x];
}
void ffxDofStoreTile(FfxUInt32x2 t, FfxFloat32x2 v) { g_state->tiles.store(t.x, t.y, v); }
static void atomicMaxWord(uint32_t word, FfxFloat32 value) {
    uint32_t bits = ffxDofAsUInt(std::max(value, 0.0f));
    uint32_t current = g_state->globals[word].load();
    while (bits > current && !g_state->globals[word].compare_exchange_weak(current, bits)) {
    }
}
void ffxDofAtomicMaxGlobalRadius(FfxFloat32 r) { atomicMaxWord(FFX_DOF_GLOBALS_MAX_RADIUS, r); }
void ffxDofAtomicMaxColorPeak(FfxFloat32 peak) { atomicMaxWord(FFX_DOF_GLOBALS_COLOR_PEAK, peak); }
FfxFloat32 ffxDofLoadColorPeak() { return ffxDofAsFloat(g_state->globals[FFX_DOF_GLOBALS_COLOR_PEAK].load()); }
void ffxDofResetColorPeak() { g_state->globals[FFX_DOF_GLOBALS_COLOR_PEAK].store(0); }
void ffxDofStoreColorScale(FfxFloat32 scale) {
    g_state->globals[FFX_DOF_GLOBALS_COLOR_SCALE].store(ffxDofAsUInt(scale));
}
FfxFloat32 ffxDofLoadColorScale() { return ffxDofAsFloat(g_state->globals[FFX_DOF_GLOBALS_COLOR_SCALE].load()); }
FfxFloat32x2 ffxDofLoadFocusCocLine() {
    return {ffxDofAsFloat(g_state->globals[FFX_DOF_GLOBALS_FOCUS_COC_SCALE].load()),
            ffxDofAsFloat(g_state->globals[FFX_DOF_GLOBALS_FOCUS_COC_BIAS].load())};
}
void ffxDofStoreHalfColor(FfxUInt32x2 t, FfxDofFloat3 c) { g_state->halfColor.store(t.x, t.y, c); }
void ffxDofStoreHalfCoc(FfxUInt32x2 t, FfxFloat32 c) { g_state->halfCoc.store(t.x, t.y, c); }
void ffxDofStoreCoarseMip(FfxUInt32 mip, FfxUInt32x2 t, FfxUInt32x2 packed) {
    if (mip == 0) throw std::out_of_range("COARSE_MIPS has no MIP 0");
    g_state->coarseMips[mip].store(t.x, t.y, packed);
}
FfxFloat32 ffxDofLoadGlobalMaxRadius() { return ffxDofAsFloat(g_state->globals[FFX_DOF_GLOBALS_MAX_RADIUS].load()); }
FfxFloat32x2 ffxDofLoadTile(FfxUInt32x2 t) { return g_state->tiles.at(int32_t(t.x), int32_t(t.y)); }
void ffxDofStoreDilatedTile(FfxUInt32x2 t, FfxFloat32x4 v) { g_state->dilatedTiles.store(t.x, t.y, v); }
FfxFloat32x4 ffxDofLoadDilatedTile(FfxUInt32x2 t) { return g_state->dilatedTiles.at(int32_t(t.x), int32_t(t.y)); }
FfxDofFloat3 ffxDofLoadHalfColor(FfxInt32x2 t) { return g_state->halfColor.at(t.x, t.y); }
FfxFloat32 ffxDofLoadHalfCoc(FfxInt32x2 t) { return g_state->halfCoc.at(t.x, t.y); }
FfxUInt32x2 ffxDofLoadCoarseMip(FfxInt32x2 t, FfxUInt32 mip) {
    if (mip == 0) throw std::out_of_range("COARSE_MIPS has no MIP 0");
    return g_state->coarseMips[mip].at(t.x, t.y);
}
void ffxDofStoreNearColor(FfxUInt32x2 t, FfxDofFloat3 c) { g_state->nearColor.store(t.x, t.y, c); }
void ffxDofStoreFarColor(FfxUInt32x2 t, FfxDofFloat3 c) { g_state->farColor.store(t.x, t.y, c); }
void ffxDofStoreLayerAlpha(FfxUInt32x2 t, FfxFloat32x2 a) {
    // LAYER_ALPHA is one R8 UNORM (ffxDofPackLayerAlpha): the opacity must already be in [0, 1] and the
    // validity 0 or 1. Kept unquantized, as the other layers are kept in 32-bit floats.
    if (a.x < 0.0f || a.x > 1.0f || (a.y != 0.0f && a.y != 1.0f)) throw std::range_error("layer alpha out of range");
    g_state->layerAlpha.store(t.x, t.y, a);
}
FfxDofFloat3 ffxDofLoadNearColor(FfxInt32x2 t) { return g_state->nearColor.at(t.x, t.y); }
FfxDofFloat3 ffxDofLoadFarColor(FfxInt32x2 t) { return g_state->farColor.at(t.x, t.y); }
FfxFloat32x2 ffxDofLoadLayerAlpha(FfxInt32x2 t) { return g_state->layerAlpha.at(t.x, t.y); }
void ffxDofStoreOutput(FfxUInt32x2 p, FfxFloat32x4 c) { g_state->output.store(p.x, p.y, c); }
void ffxDofResetGlobals() { g_state->globals[FFX_DOF_GLOBALS_MAX_RADIUS].store(0); }
void ffxDofStoreTileListArgs(FfxUInt32 list, FfxUInt32x3 groupCounts) {
    if (list >= FFX_DOF_TILE_LIST_ARGS_ENTRIES) throw std::out_of_range("tile list");
    for (uint32_t w = 0; w < 3; ++w)
        g_state->tileListArgs[list * FFX_DOF_TILE_LIST_ARGS_WORDS + w].store(groupCounts[w]);
}
void ffxDofArmColorRangeRerun(FfxUInt32x2 tileCount) {
    for (uint32_t w = 0; w < 2; ++w) {
        std::atomic<uint32_t>& word =
            g_state->tileListArgs[FFX_DOF_COLOR_RANGE_RERUN_ARGS * FFX_DOF_TILE_LIST_ARGS_WORDS + w];
        uint32_t current = word.load();
        while (tileCount[w] > current && !word.compare_exchange_weak(current, tileCount[w])) {
        }
    }
}
FfxUInt32 ffxDofCountIntoTileList(FfxUInt32 list) {
    if (list >= FFX_DOF_TILE_LIST_COUNT) throw std::out_of_range("tile list");
    return g_state->tileListArgs[list * FFX_DOF_TILE_LIST_ARGS_WORDS].fetch_add(1);
}
void ffxDofStoreTileListWord(FfxUInt32 word, FfxUInt32 packedTile) {
    // Two lists sharing an array must never meet: each word is written once.
    if (g_state->tileLists.at(word) != kUnwrittenListWord) throw std::logic_error("tile list word written twice");
    g_state->tileLists.at(word) = packedTile;
}
FfxUInt32 ffxDofLoadTileListWord(FfxUInt32 word) {
    const FfxUInt32 packed = g_state->tileLists.at(word);
    if (packed == kUnwrittenListWord) throw std::out_of_range("tile list read past its entries");
    return packed;
}
void ffxDofStoreHighlightWord(FfxUInt32 word, FfxUInt32 value) {
    g_state->highlights.at(word) = value;
    g_state->highlightWritten.at(word) = 1;
}
FfxUInt32 ffxDofLoadHighlightWord(FfxUInt32 word) {
    if (!g_state->highlightWritten.at(word)) throw std::logic_error("highlight word read before pass 2 wrote it");
    return g_state->highlights.at(word);
}

namespace ffxdoftest {

std::vector<glm::vec4> runPipeline(const Scene& scene, const Settings& settings, Layers* layers) {
    State state;
    g_state = &state;
    state.scene = &scene;
    FfxDofConstants& k = state.constants;
    k.cocScale = settings.cocScale;
    k.cocBias = settings.cocBias;
    k.cocLimit = settings.cocLimit;
    k.maxRings = settings.maxRings;
    k.fullSize = FfxUInt32x2(scene.width, scene.height);
    k.halfSize = FfxUInt32x2(ceilDiv(scene.width, 2), ceilDiv(scene.height, 2));
    k.tileCount = FfxUInt32x2(ceilDiv(k.halfSize.x, FFX_DOF_TILE_SIZE), ceilDiv(k.halfSize.y, FFX_DOF_TILE_SIZE));
    ffxdof::setApertureConstants(settings.aperture, &k);
    k.frameIndex = settings.frameIndex;
    k.outputFlags = 0;
    state.halfColor.resize(k.halfSize.x, k.halfSize.y);
    state.halfCoc.resize(k.halfSize.x, k.halfSize.y);
    for (uint32_t mip = 1; mip < FFX_DOF_OPTION_MAX_MIP; ++mip) {
        FfxUInt32x2 size = ffxDofMipSize(k.halfSize, mip);
        state.coarseMips[mip].resize(size.x, size.y);
    }
    state.tiles.resize(k.tileCount.x, k.tileCount.y);
    state.dilatedTiles.resize(k.tileCount.x, k.tileCount.y);
    state.nearColor.resize(k.halfSize.x, k.halfSize.y);
    state.farColor.resize(k.halfSize.x, k.halfSize.y);
    state.layerAlpha.resize(k.halfSize.x, k.halfSize.y);
    state.output.resize(scene.width, scene.height);
    state.tileLists.assign(ffxdof::tileListsWordCount(k.tileCount.x, k.tileCount.y), kUnwrittenListWord);
    state.highlights.assign(ffxdof::highlightsWordCount(k.tileCount.x, k.tileCount.y), kUnwrittenHighlightWord);
    state.highlightWritten.assign(state.highlights.size(), 0);

    // Group counts from the dispatch geometry of ffx_dof_resources.h.
    auto groups = [](uint32_t domain, uint32_t extent) { return ceilDiv(domain, extent); };
    runGroups(groups(scene.width, FFX_DOF_DOWNSAMPLE_DEPTH_GROUP_EXTENT),
              groups(scene.height, FFX_DOF_DOWNSAMPLE_DEPTH_GROUP_EXTENT), ffxDofDownsampleDepth);
    float globalMax = ffxDofAsFloat(state.globals[FFX_DOF_GLOBALS_MAX_RADIUS].load());
    runGroups(groups(scene.width, FFX_DOF_DOWNSAMPLE_COLOR_GROUP_EXTENT),
              groups(scene.height, FFX_DOF_DOWNSAMPLE_COLOR_GROUP_EXTENT), ffxDofDownsampleColor);
    // Pass 2's second run, as the backends dispatch it: indirectly, from the arguments its first run armed (none
    // below the range limit), with FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN.
    {
        uint32_t args[3];
        for (uint32_t w = 0; w < 3; ++w)
            args[w] = state.tileListArgs[FFX_DOF_COLOR_RANGE_RERUN_ARGS * FFX_DOF_TILE_LIST_ARGS_WORDS + w].load();
        if (args[2] != 1 || (args[0] != 0 && (args[0] != k.tileCount.x || args[1] != k.tileCount.y)))
            throw std::logic_error("pass 2's second run armed wrongly");
        if (layers) layers->colorRangeRerun = args[0] != 0;
        if (args[0] != 0) {
            k.outputFlags |= FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN;
            runGroups(args[0], args[1], ffxDofDownsampleColor);
            k.outputFlags &= ~FFX_DOF_OUTPUT_FLAG_COLOR_RANGE_RERUN;
        }
    }
    float colorPeak = ffxDofAsFloat(state.globals[FFX_DOF_GLOBALS_COLOR_PEAK].load());
    float colorScale = ffxDofAsFloat(state.globals[FFX_DOF_GLOBALS_COLOR_SCALE].load());
    runGroups(groups(k.tileCount.x, FFX_DOF_DILATE_GROUP_EXTENT), groups(k.tileCount.y, FFX_DOF_DILATE_GROUP_EXTENT),
              ffxDofDilate);
    // One indirect dispatch per class and pass, over the tiles dilate listed under it (every tile in
    // exactly one list of each pass): `runListedTile(listed tile word, its class, local index)` per invocation, as
    // the pass's entry point (ffxDofBlur, ffxDofComposite) reads the word from the list of its class.
    auto runTileLists = [&state, &k](uint32_t firstList, uint32_t classCount, auto&& runListedTile) {
        uint32_t listedTiles = 0;
        for (uint32_t tileClass = 0; tileClass < classCount; ++tileClass) {
            uint32_t args[3];
            for (uint32_t w = 0; w < 3; ++w)
                args[w] = state.tileListArgs[(firstList + tileClass) * FFX_DOF_TILE_LIST_ARGS_WORDS + w].load();
            if (args[1] != 1 || args[2] != 1) throw std::logic_error("tile list dispatch arguments not reset");
            listedTiles += args[0];
            runGroups(args[0], 1, [firstList, tileClass, &k, &runListedTile](FfxUInt32x2 group, FfxUInt32 local) {
                runListedTile(ffxDofListedTileWord(firstList + tileClass, group.x, k.tileCount.x * k.tileCount.y),
                              tileClass, local);
            });
        }
        if (listedTiles != k.tileCount.x * k.tileCount.y) throw std::logic_error("not every tile is listed once");
    };
    const bool forceMixed = settings.forceMixedBlurPath;
    runTileLists(FFX_DOF_BLUR_TILE_LIST_FIRST, FFX_DOF_BLUR_CLASS_COUNT,
                 [forceMixed](FfxUInt32 listedTile, FfxUInt32 blurClass, FfxUInt32 local) {
                     ffxDofBlurTile(listedTile, local, forceMixed ? FfxUInt32(FFX_DOF_BLUR_CLASS_MIXED) : blurClass);
                 });
    const bool forceLights = settings.forceLightsCompositePath;
    runTileLists(FFX_DOF_COMPOSITE_TILE_LIST_FIRST, FFX_DOF_COMPOSITE_CLASS_COUNT,
                 [forceLights](FfxUInt32 listedTile, FfxUInt32 compositeClass, FfxUInt32 local) {
                     const bool lights = forceLights && compositeClass == FFX_DOF_COMPOSITE_CLASS_FULL_RES;
                     ffxDofCompositeTile(listedTile, local,
                                         lights ? FfxUInt32(FFX_DOF_COMPOSITE_CLASS_LIGHTS) : compositeClass);
                 });

    if (layers) {
        layers->halfWidth = k.halfSize.x;
        layers->halfHeight = k.halfSize.y;
        layers->tilesX = k.tileCount.x;
        layers->tilesY = k.tileCount.y;
        layers->tiles = state.tiles.texels;
        layers->tileColorPeaks.clear();
        for (uint32_t y = 0; y < k.tileCount.y; ++y) {
            for (uint32_t x = 0; x < k.tileCount.x; ++x) {
                layers->tileColorPeaks.push_back(
                    ffxDofUnpackTilePeak(state.highlights.at(ffxDofHighlightPeakWord(FfxUInt32x2(x, y), k.tileCount))));
            }
        }
        layers->dilatedTiles = state.dilatedTiles.texels;
        layers->tileClasses.clear();
        for (const glm::vec4& dilated : state.dilatedTiles.texels)
            layers->tileClasses.push_back(ffxDofBlurTileClass(dilated));
        // What dilate listed: each list's entries, from the counts it left in TILE_LIST_ARGS.
        const uint32_t tileCount = k.tileCount.x * k.tileCount.y;
        layers->blurTileFlags.assign(tileCount, 0u);
        layers->compositeClasses.assign(tileCount, 0u);
        auto forEachListed = [&state, &k, tileCount](uint32_t list, auto&& visit) {
            const uint32_t entries = state.tileListArgs[list * FFX_DOF_TILE_LIST_ARGS_WORDS].load();
            for (uint32_t index = 0; index < entries; ++index) {
                const FfxUInt32 word = state.tileLists.at(ffxDofTileListWord(list, index, tileCount));
                const FfxUInt32x2 tile = ffxDofUnpackListedTile(word);
                visit(size_t(tile.y) * k.tileCount.x + tile.x, word);
            }
        };
        for (uint32_t blurClass = 0; blurClass < FFX_DOF_BLUR_CLASS_COUNT; ++blurClass)
            forEachListed(FFX_DOF_BLUR_TILE_LIST_FIRST + blurClass, [layers](size_t tile, FfxUInt32 word) {
                layers->blurTileFlags[tile] = ffxDofListedTileFlags(word);
            });
        for (uint32_t compositeClass = 0; compositeClass < FFX_DOF_COMPOSITE_CLASS_COUNT; ++compositeClass)
            forEachListed(
                FFX_DOF_COMPOSITE_TILE_LIST_FIRST + compositeClass,
                [layers, compositeClass](size_t tile, FfxUInt32) { layers->compositeClasses[tile] = compositeClass; });
        layers->coc0 = state.halfCoc.texels;
        layers->nearColor = state.nearColor.texels;
        layers->farColor = state.farColor.texels;
        layers->layerAlpha = state.layerAlpha.texels;
        layers->globalMaxRadius = globalMax;
        layers->globalsAfterComposite =
            state.globals[FFX_DOF_GLOBALS_MAX_RADIUS].load() | state.globals[FFX_DOF_GLOBALS_COLOR_PEAK].load();
        layers->colorPeak = colorPeak;
        layers->colorScale = colorScale;
    }
    g_state = nullptr;
    return state.output.texels;
}

PointDisc measurePointDisc(float radius, int position, uint32_t frame, float value) {
    const uint32_t width = 96, height = 80;
    const int px = 48 + position, py = 40 + 3 * position;
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.color.assign(size_t(width) * height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    scene.depth.assign(size_t(width) * height, radius);  // radius = -depth: far field
    scene.color[size_t(py) * width + size_t(px)] = glm::vec4(value, value, value, 1.0f);
    Settings settings;
    settings.frameIndex = frame;
    Layers layers;
    runPipeline(scene, settings, &layers);
    PointDisc disc;
    double sum = 0.0, sum2 = 0.0, count = 0.0;
    for (uint32_t y = 0; y < layers.halfHeight; ++y) {
        for (uint32_t x = 0; x < layers.halfWidth; ++x) {
            const size_t i = size_t(y) * layers.halfWidth + x;
            const double value = layers.farColor[i].x * layers.layerAlpha[i].y;
            disc.energy += value;
            const double dx = x + 0.5 - (px + 0.5) / 2.0, dy = y + 0.5 - (py + 0.5) / 2.0;
            if (dx * dx + dy * dy > 0.49 * radius * radius) continue;
            sum += value, sum2 += value * value, count += 1.0;
        }
    }
    const double mean = sum / count;
    disc.flatness = std::sqrt(std::max(0.0, sum2 / count - mean * mean)) / mean;
    return disc;
}

std::vector<LightCase> runSmallFarLightCases(float lightRadius, const std::vector<int>& sizes) {
    const uint32_t w = 128, h = 112;
    const float backgroundRadius = 16.0f;  // far field: depth = radius
    Scene plain;
    plain.width = w;
    plain.height = h;
    plain.color.assign(size_t(w) * h, glm::vec4(0.05f, 0.05f, 0.05f, 1.0f));
    plain.depth.assign(size_t(w) * h, backgroundRadius);
    Settings settings;
    settings.cocLimit = 40.0f;
    const std::vector<glm::vec4> without = runPipeline(plain, settings);
    std::vector<LightCase> cases;
    for (const int size : sizes) {
        Scene scene = plain;
        const int x0 = int(w) / 2 - size / 2, y0 = int(h) / 2 - size / 2;
        for (int y = y0; y < y0 + size; ++y)
            for (int x = x0; x < x0 + size; ++x) {
                scene.color[size_t(y) * w + size_t(x)] = glm::vec4(50.0f, 50.0f, 50.0f, 1.0f);
                scene.depth[size_t(y) * w + size_t(x)] = lightRadius;
            }
        const std::vector<glm::vec4> out = runPipeline(scene, settings);
        LightCase light;
        light.size = size;
        for (size_t i = 0; i < out.size(); ++i) light.energyAdded += out[i].y - without[i].y;
        light.inputEnergy = double(size * size) * (50.0 - 0.05);
        const double discRadius = 2.0 * lightRadius;  // full-res px
        const double coverage = size * size / (3.14159265 * discRadius * discRadius);
        light.discLevel = 50.0 * coverage + 0.05 * (1.0 - coverage);
        light.centre = out[size_t(h / 2) * w + w / 2].y;
        cases.push_back(light);
    }
    return cases;
}

}  // namespace ffxdoftest
