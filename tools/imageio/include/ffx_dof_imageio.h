// Image file input and output for the ffx-dof tools and tests: OpenEXR (half or float) and 8-bit PNG.
//
// Pixels are linear floats in memory. Every writer goes through a temporary file in the target's
// directory, fsync() and rename(): an existing file is only replaced once the new one is complete, and
// on any failure the temporary file is removed and the old file is left as it was. A symbolic link is
// followed (its target is replaced, the link stays); the replacement keeps the replaced file's mode; a
// read-only existing file (owner write bit off) is refused. Write failures read
// "cannot write <path>: <reason>" (e.g. "No space left on device").
//
// Readers check the header before allocating pixel memory: a data window other than the display
// window, a side above 16384 pixels, or fewer pixels in the file than the header claims (a truncated
// or doctored file) is refused.
//
// Every failure throws IoError with a one-line message that names the file and the problem (missing,
// not an EXR or corrupt, wrong channel count, no such channel with the list of those that exist,
// deep data, unwritable directory, ...). Corrupt files never crash: the library's exceptions are caught
// and rethrown as IoError.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ffxdof::io {

class IoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Four channels per pixel, RGBA interleaved, rows top to bottom, linear (not sRGB encoded).
struct ImageRGBA {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> pixels;  // width * height * 4 values

    ImageRGBA() = default;
    ImageRGBA(uint32_t w, uint32_t h) : width(w), height(h), pixels(size_t(w) * h * 4, 0.0f) {}
    float* at(uint32_t x, uint32_t y) { return &pixels[(size_t(y) * width + x) * 4]; }
    const float* at(uint32_t x, uint32_t y) const { return &pixels[(size_t(y) * width + x) * 4]; }
};

// One channel per pixel (depth, masks, CoC radius), rows top to bottom.
struct ImageR {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> pixels;  // width * height values

    ImageR() = default;
    ImageR(uint32_t w, uint32_t h) : width(w), height(h), pixels(size_t(w) * h, 0.0f) {}
    float& at(uint32_t x, uint32_t y) { return pixels[size_t(y) * width + x]; }
    float at(uint32_t x, uint32_t y) const { return pixels[size_t(y) * width + x]; }
};

enum class ExrPixelType { Half, Float };

// Reads colour from an EXR file (single-part, multi-part or multilayer). With an empty layerPrefix it
// takes the default (unnamed) layer's R, G, B; otherwise "<layerPrefix>.R" etc. (e.g. "beauty"). A
// missing A channel reads as 1. Throws IoError when R, G or B is missing, listing the channels present.
ImageRGBA readExrColor(const std::string& path, const std::string& layerPrefix = "");

// Reads one channel from an EXR file. With an empty channelName the file (or its first part) must hold
// exactly one channel; otherwise the named channel (e.g. "Z", "depth.Z", "Depth.V") is read from
// whichever part holds it. Throws IoError listing the channels present when the name is not found or
// when an empty name meets a file with several channels.
ImageR readExrChannel(const std::string& path, const std::string& channelName = "");

// Lists "name" for every channel of every part (for error messages and tools).
std::vector<std::string> listExrChannels(const std::string& path);

// Writes R, G, B, A as one EXR part (ZIP compression).
void writeExr(const std::string& path, const ImageRGBA& image, ExrPixelType type = ExrPixelType::Half);
// Writes one channel named channelName ("Y" by default, which viewers show as grey; use "Z" for depth).
void writeExr(const std::string& path, const ImageR& image, ExrPixelType type = ExrPixelType::Float,
              const std::string& channelName = "Y");

// ---- sequences (ffx-dof apply over frames) --------------------------------------------------------

// What a writer does when the destination exists when the new file is complete. Replace: the new file
// replaces it (rename). Keep: the existing file stays and the new one is discarded (renameat2 with
// RENAME_NOREPLACE, or link() where the file system lacks it): of several processes writing the same
// file at once, exactly one file lands, whole, and no temporary file is left.
enum class IfExists { Replace, Keep };

// What the header and offset table of an EXR file say, read without its pixels.
struct ExrProbe {
    uint32_t width = 0, height = 0;     // of the first part's data window
    bool complete = false;              // every part has its chunks; the first part decodes whole
    std::vector<std::string> channels;  // of every part, as listExrChannels
};
// Throws IoError when the file is missing, not an OpenEXR file, or its header is unreadable.
ExrProbe probeExr(const std::string& path);

// The channels of an EXR part other than one colour layer's R, G, B, A, in their own pixel types,
// and the part's header attributes: what --keep-layers copies into the output.
class ExrKeptLayers {
public:
    struct Impl;
    ExrKeptLayers();
    ~ExrKeptLayers();
    ExrKeptLayers(ExrKeptLayers&&) noexcept;
    ExrKeptLayers& operator=(ExrKeptLayers&&) noexcept;
    std::vector<std::string> channelNames() const;
    std::unique_ptr<Impl> impl;
};
// Reads the part that holds layerPrefix's R (the default layer's R for an empty prefix). Subsampled
// channels are refused (IoError).
ExrKeptLayers readExrKeptLayers(const std::string& path, const std::string& layerPrefix = "");

struct ExrWriteOptions {
    ExrPixelType type = ExrPixelType::Half;
    IfExists ifExists = IfExists::Replace;
    std::string layerPrefix;              // the image is written as <prefix>.R, ... (empty: R, G, B, A)
    const ExrKeptLayers* kept = nullptr;  // also written: its channels and header attributes
};
// Writes R, G, B, A (and the kept layers) as one EXR part (ZIP compression). Returns false, leaving
// the existing file as it is, when options.ifExists is Keep and the destination exists.
bool writeExr(const std::string& path, const ImageRGBA& image, const ExrWriteOptions& options);

// Writes an 8-bit sRGB-encoded PNG (libpng). Colour is clamped to [0, 1] before encoding; alpha is
// written linearly when withAlpha, otherwise the file is RGB.
void writePng(const std::string& path, const ImageRGBA& image, bool withAlpha = false);

// Chooses the format from the extension (.exr: EXR of exrType, .png: PNG without alpha; case-insensitive).
// Throws IoError for any other extension.
void writeImage(const std::string& path, const ImageRGBA& image, ExrPixelType exrType = ExrPixelType::Half);

// Writes any file the same safe way as the image writers: writer fills a stream on a temporary file
// in the destination's directory, which then replaces path. Throws IoError (the destination untouched)
// when the directory is missing or unwritable, the stream fails, or writer throws (rethrown as is).
void writeFileReplacing(const std::string& path, const std::function<void(std::ostream&)>& writer);

// True when the path ends in the extension (".exr", ".png"), ignoring case.
bool hasExtension(const std::string& path, const std::string& extension);

}  // namespace ffxdof::io
