// ffx-dof apply: EXR color + depth in, the effect on Vulkan, EXR or PNG out; one frame, or a sequence
// of frames (--frames) read, computed and written in overlapping stages (docs/cli.md, "Sequences").
#include "cli_error.h"
#include "commands.h"
#include "effect_run.h"
#include "interrupt.h"
#include "sequence.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include <sys/stat.h>
#include <unistd.h>

namespace ffxdof::cli {
namespace {

// Everything that can be checked without reading a file, so a typo costs no device start-up.
void checkArguments(const ApplyOptions& options, bool sequence) {
    if (!io::hasExtension(options.outputPath, ".exr") && !io::hasExtension(options.outputPath, ".png")) {
        throw CliError(ExitCode::Usage, "--out must end in .exr or .png: " + options.outputPath);
    }
    for (const std::string* input : {&options.colorPath, &options.depthPath}) {
        if (!io::hasExtension(*input, ".exr")) {
            throw CliError(ExitCode::InputFile, "inputs must be OpenEXR files (.exr): " + *input);
        }
    }
    if (options.outType != "auto" && !io::hasExtension(options.outputPath, ".exr")) {
        throw CliError(ExitCode::Usage, "--out-type applies to .exr outputs only: " + options.outputPath);
    }
    if (options.keepLayers && !io::hasExtension(options.outputPath, ".exr")) {
        throw CliError(ExitCode::Usage, "--keep-layers needs an .exr output: " + options.outputPath);
    }
    if (!options.focusGiven && !options.autofocus && options.cameraTrack.empty()) {
        throw CliError(ExitCode::Usage, "--focus is required (or --autofocus X,Y, or a --camera-track that gives it)");
    }
    if (options.autofocus) checkAutofocusRegion(*options.autofocus);
    if (!sequence) {
        for (const auto& [option, given] :
             {std::pair{"--chunk", !options.chunk.empty()}, std::pair{"--camera-track", !options.cameraTrack.empty()},
              std::pair{"--overwrite", options.overwrite}, std::pair{"--no-overlap", options.noOverlap}}) {
            if (given) throw CliError(ExitCode::Usage, std::string(option) + " needs --frames");
        }
    } else if (!io::hasExtension(options.outputPath, ".exr")) {
        throw CliError(ExitCode::Usage, "a sequence's --out must be .exr: " + options.outputPath);
    }
    checkEffectOptions(options.effect);
}

// Writing the output over an input would destroy it (and a depth file turned into RGBA breaks the next
// run). Files are compared by device and inode, with symbolic links followed, so every spelling of the
// same file is caught: "./c.exr", an absolute path, a symbolic link, a hard link.
void checkOutputIsNoInput(const std::string& outputPath, const std::string& colorPath, const std::string& depthPath) {
    struct stat output {};
    if (::stat(outputPath.c_str(), &output) != 0) return;  // not there yet: it cannot be an input
    for (const auto& [option, path] : {std::pair{"--color", &colorPath}, std::pair{"--depth", &depthPath}}) {
        struct stat input {};
        if (::stat(path->c_str(), &input) == 0 && input.st_dev == output.st_dev && input.st_ino == output.st_ino) {
            throw CliError(ExitCode::Usage, "--out " + outputPath + " is the same file as " + option + " " + *path +
                                                "; writing it would destroy the input");
        }
    }
}

DepthProjection deviceProjection(const ApplyOptions& options) {
    if (options.projection) {
        return projectionFromMatrix(*options.projection, options.reverseDepth);
    }
    return projectionFromNearFar(*options.nearPlane, *options.farPlane, options.reverseDepth);
}

// ---- one frame: read, compute, write ----------------------------------------------------------------

struct FrameFiles {
    int64_t frame = -1;  // -1: not a sequence
    std::string color, depth, output;
};

struct PreparedFrame {
    FrameFiles files;
    uint32_t width = 0, height = 0;
    io::ImageRGBA color;
    vkrun::HostImage depth;  // device depth for the effect
    CocParameters coc;       // with autofocus: the chosen focus's, once the effect ran
    bool reversed = false;
    ThinLens lens;  // with autofocus: focusDistance is the chosen one once the effect ran
    DepthProjection projection;
    std::string projectionOrigin;
    std::optional<FfxDofAutofocus> autofocus;
    float largestRadius = 0.0f;  // half-res px
    double cocLimit = 0.0;       // the cocLimitFactor used
    size_t clampedPixels = 0;    // full-res pixels whose radius exceeds the limit (0 when it follows the image)
    std::optional<io::ExrKeptLayers> kept;
    io::IfExists ifExists = io::IfExists::Replace;
};

// Full-resolution pixels whose radius exceeds a --coc-limit (none when the limit follows the image).
void countClampedPixels(const ApplyOptions& options, const std::vector<float>& deviceDepth, PreparedFrame& frame) {
    frame.clampedPixels = 0;
    if (options.effect.cocLimitFollowsImage) return;
    const float radiusLimit = float(frame.cocLimit * frame.height * 0.5);
    for (float d : deviceDepth)
        frame.clampedPixels += std::fabs(d * frame.coc.cocScale + frame.coc.cocBias) > radiusLimit;
}

PreparedFrame prepareFrame(const ApplyOptions& options, const FrameFiles& files, const LensSettings& lensSettings) {
    PreparedFrame frame;
    frame.files = files;
    checkOutputIsNoInput(files.output, files.color, files.depth);
    frame.lens = makeThinLens(lensSettings, options.autofocus.has_value());
    // Validates the projection before the (possibly large) files are read.
    std::optional<DepthProjection> projection;
    if (options.depthKind == DepthKind::Device) {
        projection = deviceProjection(options);
        if (options.autofocus) (void)autofocusRange(frame.lens, *projection);
    }
    frame.color = readInput([&] { return io::readExrColor(files.color, options.colorLayer); });
    const io::ImageR depth = readInput([&] { return io::readExrChannel(files.depth, options.depthChannel); });
    checkResolutions(frame.color, files.color, depth, files.depth);
    checkColorFinite(frame.color, files.color);
    frame.width = frame.color.width;
    frame.height = frame.color.height;
    if (options.keepLayers) {
        frame.kept = readInput([&] { return io::readExrKeptLayers(files.color, options.colorLayer); });
    }

    EffectDepth effectDepth;
    if (options.depthKind == DepthKind::Linear) {
        effectDepth = linearToEffectDepth(depth, files.depth);
    } else {
        checkDeviceDepth(depth, files.depth);
        effectDepth.deviceDepth = depth.pixels;
        effectDepth.projection = *projection;
        effectDepth.projectionOrigin = options.projection ? "--proj" : "--near/--far";
    }
    frame.projection = effectDepth.projection;
    frame.projectionOrigin = effectDepth.projectionOrigin;
    frame.reversed = effectDepth.projection.reversed;
    if (options.autofocus) {
        // The focus is chosen on the device; the CoC limit must hold the radii of every focus it can choose.
        const FocusRange range = autofocusRange(frame.lens, frame.projection);
        frame.autofocus = makeAutofocus(frame.lens, frame.projection, frame.width, *options.autofocus, range);
        const FocusRange reachable = reachableAutofocus(effectDepth.deviceDepth, frame.width, frame.height,
                                                        frame.projection, *options.autofocus, range);
        for (const double focus : {reachable.nearest, reachable.farthest}) {
            ThinLens at = frame.lens;
            at.focusDistance = focus;
            const CocParameters coc = computeCocParameters(at, frame.projection, frame.width, frame.projectionOrigin);
            frame.largestRadius = std::fmax(frame.largestRadius, largestCocRadius(effectDepth.deviceDepth, coc));
        }
    } else {
        frame.coc = computeCocParameters(frame.lens, frame.projection, frame.width, frame.projectionOrigin);
        frame.largestRadius = largestCocRadius(effectDepth.deviceDepth, frame.coc);
    }
    frame.cocLimit = effectiveCocLimit(options.effect, frame.largestRadius, frame.color.height);
    if (!options.autofocus) countClampedPixels(options, effectDepth.deviceDepth, frame);
    frame.depth = toHostImage(depth.width, depth.height, effectDepth.deviceDepth);
    return frame;
}

struct ComputedFrame {
    PreparedFrame prepared;
    io::ImageRGBA output;
};

ComputedFrame computeFrame(const ApplyOptions& options, vkrun::Device& device, vkrun::EffectSession& session,
                           PreparedFrame prepared) {
    EffectOptions effect = options.effect;
    effect.cocLimit = prepared.cocLimit;
    float focus = 0.0f;
    const vkrun::HostImage output = runEffectOrThrow(
        device, session, toHostImage(prepared.color), prepared.depth,
        makeRunSettings(effect, prepared.coc, prepared.reversed, prepared.autofocus ? &*prepared.autofocus : nullptr),
        &focus);
    if (prepared.autofocus) {
        // What the chosen focus did: the image's radii and clamp, as for a --focus of that distance.
        prepared.lens.focusDistance = focus;
        prepared.coc =
            computeCocParameters(prepared.lens, prepared.projection, prepared.width, prepared.projectionOrigin);
        prepared.largestRadius = largestCocRadius(prepared.depth.pixels, prepared.coc);
        countClampedPixels(options, prepared.depth.pixels, prepared);
    }
    ComputedFrame computed;
    computed.output = toImageRGBA(output);
    prepared.color = {};  // the input's memory is not needed any more
    prepared.depth = {};
    computed.prepared = std::move(prepared);
    return computed;
}

struct WrittenFrame {
    bool landed = true;  // false: another process wrote the file first (IfExists::Keep)
    io::ExrPixelType type = io::ExrPixelType::Half;
};

WrittenFrame writeFrame(const ApplyOptions& options, const ComputedFrame& frame) {
    const std::string& path = frame.prepared.files.output;
    WrittenFrame written;
    written.type = chooseExrPixelType(options.outType, frame.output, path);
    if (!io::hasExtension(path, ".exr")) {
        writeOutput(path, frame.output, written.type);
        return written;
    }
    io::ExrWriteOptions exr;
    exr.type = written.type;
    exr.ifExists = frame.prepared.ifExists;
    if (frame.prepared.kept) {
        exr.kept = &*frame.prepared.kept;
        exr.layerPrefix = options.colorLayer;  // the result replaces the layer it was computed from
    }
    try {
        written.landed = io::writeExr(path, frame.output, exr);
    } catch (const io::IoError& error) {
        throw CliError(ExitCode::OutputWrite, error.what());
    }
    return written;
}

// Without --coc-limit, whether the radii reached the largest automatic limit (the image height). With
// autofocus the limit covers every focus it could choose: the chosen one may stay below it.
bool clampsAtImageHeight(const ApplyOptions& options, const PreparedFrame& frame) {
    return options.effect.cocLimitFollowsImage && frame.cocLimit >= kLargestAutoCocLimit &&
           (!frame.autofocus || frame.largestRadius > frame.cocLimit * frame.height * 0.5);
}

std::string clampLine(const ApplyOptions& options, const PreparedFrame& frame) {
    char line[320];
    const size_t pixels = size_t(frame.width) * frame.height;
    const double radiusLimit = frame.cocLimit * frame.height * 0.5;
    if (options.effect.cocLimitFollowsImage) {
        std::snprintf(line, sizeof(line),
                      "largest CoC radius %.2f half-res px; no clamp (the limit follows the image: "
                      "cocLimitFactor %.4g; --coc-limit L clamps at L x the image height)",
                      frame.largestRadius, frame.cocLimit);
        if (clampsAtImageHeight(options, frame)) {
            std::snprintf(line, sizeof(line),
                          "largest CoC radius %.2f half-res px, clamped at %.2f (the image height, the largest "
                          "limit without --coc-limit)",
                          frame.largestRadius, radiusLimit);
        }
    } else if (frame.clampedPixels > 0) {
        std::snprintf(line, sizeof(line),
                      "--coc-limit %g clamps %zu pixels (%.1f%%) whose CoC radius exceeds %.2f half-res px (largest "
                      "%.2f); without --coc-limit nothing is clamped",
                      options.effect.cocLimit, frame.clampedPixels,
                      100.0 * double(frame.clampedPixels) / double(pixels), radiusLimit, frame.largestRadius);
    } else {
        std::snprintf(line, sizeof(line), "largest CoC radius %.2f half-res px, limit %.2f (--coc-limit %g): no clamp",
                      frame.largestRadius, radiusLimit, options.effect.cocLimit);
    }
    return line;
}

// ---- one file -----------------------------------------------------------------------------------------

void runSingle(const ApplyOptions& options) {
    const FrameFiles files{-1, options.colorPath, options.depthPath, options.outputPath};
    PreparedFrame prepared = prepareFrame(options, files, options.lens);
    std::unique_ptr<vkrun::Device> device = openDevice(options.effect);
    vkrun::EffectSession session(*device);
    const uint32_t width = prepared.width, height = prepared.height;
    const ComputedFrame computed = computeFrame(options, *device, session, std::move(prepared));
    throwIfInterrupted("nothing was written to " + options.outputPath);
    const WrittenFrame written = writeFrame(options, computed);
    const bool exr = io::hasExtension(options.outputPath, ".exr");
    std::printf("wrote %s (%ux%u%s) on %s\n", options.outputPath.c_str(), width, height,
                exr ? (written.type == io::ExrPixelType::Half ? ", half" : ", float") : "", device->name().c_str());
    if (options.autofocus) {
        std::printf("%s (autofocus at %g,%g, region %g)\n", focusText(computed.prepared.lens.focusDistance).c_str(),
                    options.autofocus->x, options.autofocus->y, options.autofocus->size);
    }
    std::printf("%s; aperture radius %.4g m\n", clampLine(options, computed.prepared).c_str(),
                computed.prepared.lens.apertureRadius);
}

// ---- sequences ------------------------------------------------------------------------------------------

// A bounded queue between two stages. abort() wakes every waiter and makes push and pop fail.
template <typename T>
class Stage {
public:
    explicit Stage(size_t capacity) : capacity_(capacity) {}
    bool push(T value) {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!aborted_ && items_.size() >= capacity_) wait(lock);
        if (aborted_) return false;
        items_.push_back(std::move(value));
        changed_.notify_all();
        return true;
    }
    // Empty when the producer finished (close) and everything was taken, or on abort.
    std::optional<T> pop() {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!aborted_ && !closed_ && items_.empty()) wait(lock);
        if (aborted_ || items_.empty()) return std::nullopt;
        T value = std::move(items_.front());
        items_.pop_front();
        changed_.notify_all();
        return value;
    }
    void close() {
        std::lock_guard<std::mutex> lock(mutex_);
        closed_ = true;
        changed_.notify_all();
    }
    void abort() {
        std::lock_guard<std::mutex> lock(mutex_);
        aborted_ = true;
        items_.clear();
        changed_.notify_all();
    }

private:
    // A signal cannot notify a condition variable: waiters look at the flag every 50 ms.
    void wait(std::unique_lock<std::mutex>& lock) {
        changed_.wait_for(lock, std::chrono::milliseconds(50));
        if (interruptSignal() != 0) aborted_ = true;
    }
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<T> items_;
    size_t capacity_;
    bool closed_ = false, aborted_ = false;
};

enum class FrameStatus { Missing, Complete, Invalid };

// Whether a frame's output is already there and whole: a readable EXR, every chunk present, the size of
// the frame's color input, and the channels apply writes.
FrameStatus outputStatus(const ApplyOptions& options, const FrameFiles& files, std::string& why) {
    struct stat existing {};
    if (::stat(files.output.c_str(), &existing) != 0) return FrameStatus::Missing;
    io::ExrProbe output;
    try {
        output = io::probeExr(files.output);
    } catch (const io::IoError& error) {
        why = error.what();
        return FrameStatus::Invalid;
    }
    if (!output.complete) {
        why = "it is incomplete";
        return FrameStatus::Invalid;
    }
    for (const char* channel : {"R", "G", "B", "A"}) {
        const std::string name =
            options.keepLayers && !options.colorLayer.empty() ? options.colorLayer + "." + channel : channel;
        if (std::find(output.channels.begin(), output.channels.end(), name) == output.channels.end()) {
            why = "it has no channel " + name;
            return FrameStatus::Invalid;
        }
    }
    try {
        const io::ExrProbe input = io::probeExr(files.color);
        if (input.width != output.width || input.height != output.height) {
            why = "it is " + std::to_string(output.width) + "x" + std::to_string(output.height) + ", the input " +
                  std::to_string(input.width) + "x" + std::to_string(input.height);
            return FrameStatus::Invalid;
        }
    } catch (const io::IoError&) {
        // The input's problem is reported when the frame is read.
        why = "its input cannot be read";
        return FrameStatus::Invalid;
    }
    return FrameStatus::Complete;
}

// Progress: one updating line on a terminal, plain lines otherwise; the summary at the end.
class Progress {
public:
    Progress(size_t total, std::string range) : total_(total), range_(std::move(range)), tty_(::isatty(1) == 1) {
        start_ = std::chrono::steady_clock::now();
    }
    void skipped(int64_t frame, const std::string& why) {
        ++skipped_;
        ++done_;
        line("frame " + std::to_string(frame) + ": skipped, " + why);
    }
    void note(int64_t frame, const std::string& text) { line("frame " + std::to_string(frame) + ": " + text); }
    // focus: "focus: 2.48 m" with autofocus, else empty.
    void written(int64_t frame, const std::string& path, io::ExrPixelType type, const std::string& focus) {
        ++written_;
        ++done_;
        if (firstWritten_ == std::chrono::steady_clock::time_point{}) firstWritten_ = std::chrono::steady_clock::now();
        char status[200];
        std::snprintf(status, sizeof(status), "%zu/%zu frames, %.2f fps, %s left", done_, total_, fps(),
                      timeLeft().c_str());
        if (tty_) {
            status_ = status;
            std::printf("\r\033[K%s (frame %lld%s%s)", status, static_cast<long long>(frame), focus.empty() ? "" : ", ",
                        focus.c_str());
            std::fflush(stdout);
        } else {
            std::printf("frame %lld: wrote %s (%s); %s%s%s\n", static_cast<long long>(frame), path.c_str(),
                        type == io::ExrPixelType::Half ? "half" : "float", focus.c_str(), focus.empty() ? "" : "; ",
                        status);
            std::fflush(stdout);
        }
    }
    // stageSeconds: time spent reading, computing and writing (they overlap unless --no-overlap).
    void summary(const std::string& device, float largestRadius, const double (&stageSeconds)[3]) {
        if (tty_ && !status_.empty()) std::printf("\r\033[K");
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        std::printf(
            "done: %zu frames (%s) on %s: written %zu, skipped %zu, in %.1f s, %.2f fps (read %.1f s, "
            "effect %.1f s, write %.1f s); largest CoC radius %.2f half-res px\n",
            total_, range_.c_str(), device.c_str(), written_, skipped_, seconds, fps(), stageSeconds[0],
            stageSeconds[1], stageSeconds[2], largestRadius);
        std::fflush(stdout);
    }
    size_t written() const { return written_; }
    size_t skippedCount() const { return skipped_; }

private:
    void line(const std::string& text) {
        if (tty_ && !status_.empty()) {
            std::printf("\r\033[K%s\n%s", text.c_str(), status_.c_str());
        } else {
            std::printf("%s\n", text.c_str());
        }
        std::fflush(stdout);
    }
    double fps() const {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        return seconds > 0.0 ? double(written_) / seconds : 0.0;
    }
    std::string timeLeft() const {
        const double rate = fps();
        if (rate <= 0.0) return "?";
        const long long seconds = std::llround(double(total_ - done_) / rate);
        char text[32];
        if (seconds >= 3600) {
            std::snprintf(text, sizeof(text), "%lldh%02lldm", seconds / 3600, seconds / 60 % 60);
        } else if (seconds >= 60) {
            std::snprintf(text, sizeof(text), "%lldm%02llds", seconds / 60, seconds % 60);
        } else {
            std::snprintf(text, sizeof(text), "%llds", seconds);
        }
        return text;
    }
    size_t total_, done_ = 0, written_ = 0, skipped_ = 0;
    std::string range_, status_;
    bool tty_;
    std::chrono::steady_clock::time_point start_, firstWritten_{};
};

// What travels from stage to stage: a frame to skip, or its data.
struct ReadItem {
    std::exception_ptr error;  // the frame (and every later one) failed: passed on, so earlier frames finish
    FrameFiles files;
    std::string skipReason;  // not empty: skip the frame
    std::optional<PreparedFrame> prepared;
};
struct ComputedItem {
    std::exception_ptr error;
    FrameFiles files;
    std::string skipReason;
    std::optional<ComputedFrame> computed;
};

class SequenceRun {
public:
    SequenceRun(const ApplyOptions& options, std::vector<int64_t> frames)
        : options_(options),
          frames_(std::move(frames)),
          color_(options.colorPath, "--color"),
          depth_(options.depthPath, "--depth"),
          output_(options.outputPath, "--out") {
        if (!output_.hasField()) {
            throw CliError(ExitCode::Usage,
                           "--frames needs a frame-number field in --out (e.g. dof.####.exr or "
                           "dof.%04d.exr): " +
                               options.outputPath);
        }
        if (!options.cameraTrack.empty()) track_ = readCameraTrack(options.cameraTrack);
        // Every frame's lens is checked before any work, so a bad track entry fails at once.
        for (int64_t frame : frames_) {
            const auto entry = track_.find(frame);
            if (options.autofocus && entry != track_.end() && entry->second.focusMetres) {
                throw CliError(ExitCode::Usage, "--autofocus chooses the focus, but " + options.cameraTrack +
                                                    " gives one for frame " + std::to_string(frame) +
                                                    "; drop its focus values or --autofocus");
            }
            (void)makeThinLens(lensForFrame(options.lens, track_, frame, options.cameraTrack),
                               options.autofocus.has_value());
        }
    }

    void run() {
        installInterruptHandlers();
        device_ = openDevice(options_.effect);
        session_ = std::make_unique<vkrun::EffectSession>(*device_);
        progress_ = std::make_unique<Progress>(frames_.size(), rangeText());
        if (options_.noOverlap) {
            runSerial();
        } else {
            runOverlapped();
        }
        if (error_) std::rethrow_exception(error_);
        throwIfInterrupted(std::to_string(progress_->written()) + " frames written, " +
                           std::to_string(progress_->skippedCount()) + " skipped; every written frame is whole");
        const double stageSeconds[3] = {stageSeconds_[0].load(), stageSeconds_[1].load(), stageSeconds_[2].load()};
        progress_->summary(device_->name(), largestRadius_, stageSeconds);
    }

private:
    std::string rangeText() const {
        return frames_.size() == 1 ? std::to_string(frames_.front())
                                   : std::to_string(frames_.front()) + " to " + std::to_string(frames_.back());
    }

    FrameFiles filesOf(int64_t frame) const {
        return {frame, color_.path(frame), depth_.path(frame), output_.path(frame)};
    }

    // Stage 1: decide whether the frame is done already, otherwise read and check it.
    // Adds the time until it goes out of scope to one stage's total.
    class StageTimer {
    public:
        explicit StageTimer(std::atomic<double>& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
        ~StageTimer() {
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
            double old = total_.load();
            while (!total_.compare_exchange_weak(old, old + seconds)) {
            }
        }

    private:
        std::atomic<double>& total_;
        std::chrono::steady_clock::time_point start_;
    };

    ReadItem read(int64_t frame) {
        const StageTimer timer(stageSeconds_[0]);
        ReadItem item;
        item.files = filesOf(frame);
        io::IfExists ifExists = io::IfExists::Keep;
        if (options_.overwrite) {
            ifExists = io::IfExists::Replace;
        } else {
            std::string why;
            switch (outputStatus(options_, item.files, why)) {
                case FrameStatus::Complete:
                    item.skipReason = item.files.output + " is complete (--overwrite redoes it)";
                    return item;
                case FrameStatus::Invalid:
                    // Not a finished frame of ours: replaced once the new one is complete.
                    ifExists = io::IfExists::Replace;
                    note(frame, "redoing " + item.files.output + ": " + why);
                    break;
                case FrameStatus::Missing:
                    break;
            }
        }
        item.prepared =
            prepareFrame(options_, item.files, lensForFrame(options_.lens, track_, frame, options_.cameraTrack));
        item.prepared->ifExists = ifExists;
        return item;
    }

    // Stage 2: the effect on the device (this thread only submits).
    ComputedItem compute(ReadItem item) {
        const StageTimer timer(stageSeconds_[1]);
        ComputedItem computed;
        computed.error = item.error;
        computed.files = item.files;
        if (item.error) return computed;
        computed.skipReason = item.skipReason;
        if (item.prepared) {
            computed.computed = computeFrame(options_, *device_, *session_, std::move(*item.prepared));
            const PreparedFrame& prepared = computed.computed->prepared;
            largestRadius_ = std::max(largestRadius_, prepared.largestRadius);
            if (prepared.clampedPixels > 0 || clampsAtImageHeight(options_, prepared)) {
                note(item.files.frame, clampLine(options_, prepared));
            }
        }
        return computed;
    }

    // Stage 3: write (or find that another process wrote the frame first) and report.
    void write(const ComputedItem& item) {
        if (item.error) std::rethrow_exception(item.error);
        if (!item.computed) {
            std::lock_guard<std::mutex> lock(progressMutex_);
            progress_->skipped(item.files.frame, item.skipReason);
            return;
        }
        WrittenFrame written;
        {
            const StageTimer timer(stageSeconds_[2]);
            written = writeFrame(options_, *item.computed);
        }
        std::lock_guard<std::mutex> lock(progressMutex_);
        if (written.landed) {
            const PreparedFrame& prepared = item.computed->prepared;
            progress_->written(item.files.frame, item.files.output, written.type,
                               prepared.autofocus ? focusText(prepared.lens.focusDistance) : std::string());
        } else {
            progress_->skipped(item.files.frame, item.files.output + " was written by another process meanwhile");
        }
    }

    void note(int64_t frame, const std::string& text) {
        std::lock_guard<std::mutex> lock(progressMutex_);
        progress_->note(frame, text);
    }

    void runSerial() {
        try {
            for (int64_t frame : frames_) {
                if (interruptSignal()) return;
                ReadItem item = read(frame);
                if (interruptSignal()) return;
                ComputedItem computed = compute(std::move(item));
                if (interruptSignal()) return;  // a computed frame is abandoned, never half-written
                write(computed);
            }
        } catch (...) {
            error_ = std::current_exception();
        }
    }

    // Reading frame N+1 (a thread), computing frame N (this thread) and writing frame N-1 (a thread)
    // overlap; the queues hold one frame each, so at most four frames are in memory.
    void runOverlapped() {
        Stage<ReadItem> readQueue(1);
        Stage<ComputedItem> writeQueue(1);
        std::mutex errorMutex;
        const auto fail = [&](std::exception_ptr error) {
            {
                std::lock_guard<std::mutex> lock(errorMutex);
                if (!error_) error_ = error;
            }
            readQueue.abort();
            writeQueue.abort();
        };
        std::thread reader([&] {
            for (int64_t frame : frames_) {
                ReadItem item;
                try {
                    item = read(frame);
                } catch (...) {
                    item.error = std::current_exception();
                }
                const bool failed = bool(item.error);
                if (interruptSignal() || !readQueue.push(std::move(item)) || failed) break;
            }
            readQueue.close();
        });
        std::thread writer([&] {
            try {
                while (std::optional<ComputedItem> item = writeQueue.pop()) {
                    if (interruptSignal()) break;  // a computed frame is abandoned, never half-written
                    write(*item);
                }
            } catch (...) {
                fail(std::current_exception());
            }
        });
        while (std::optional<ReadItem> item = readQueue.pop()) {
            if (interruptSignal()) break;
            ComputedItem computed;
            try {
                computed = compute(std::move(*item));
            } catch (...) {
                computed.error = std::current_exception();
            }
            const bool failed = bool(computed.error);
            if (!writeQueue.push(std::move(computed)) || failed) break;
        }
        readQueue.abort();  // after an error the reader stops too
        writeQueue.close();
        if (interruptSignal()) {
            readQueue.abort();
            writeQueue.abort();
        }
        reader.join();
        writer.join();
    }

    const ApplyOptions& options_;
    std::vector<int64_t> frames_;
    FramePattern color_, depth_, output_;
    CameraTrack track_;
    std::unique_ptr<vkrun::Device> device_;
    std::unique_ptr<vkrun::EffectSession> session_;
    std::unique_ptr<Progress> progress_;
    std::mutex progressMutex_;
    float largestRadius_ = 0.0f;
    std::atomic<double> stageSeconds_[3] = {0.0, 0.0, 0.0};  // read, effect, write
    std::exception_ptr error_;
};

}  // namespace

void runApply(const ApplyOptions& options) {
    const bool sequence = !options.frames.empty();
    checkArguments(options, sequence);
    if (!sequence) {
        for (const auto& [option, path] :
             {std::pair{"--color", &options.colorPath}, std::pair{"--depth", &options.depthPath},
              std::pair{"--out", &options.outputPath}}) {
            if (FramePattern(*path, option).hasField()) {
                throw CliError(ExitCode::Usage, std::string(option) + " " + *path +
                                                    " has a frame-number field; give the frames with --frames");
            }
        }
        installInterruptHandlers();
        runSingle(options);
        return;
    }
    std::vector<int64_t> frames = parseFrameList(options.frames);
    if (!options.chunk.empty()) frames = chunkOf(frames, parseChunk(options.chunk));
    if (frames.empty()) {
        std::printf("done: this chunk (%s) of --frames %s holds no frame\n", options.chunk.c_str(),
                    options.frames.c_str());
        return;
    }
    SequenceRun(options, std::move(frames)).run();
}

}  // namespace ffxdof::cli
