#include "ffx_dof_imageio.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputPart.h>
#include <ImfMultiPartInputFile.h>
#include <ImfOutputFile.h>
#include <ImfPartType.h>
#include <ImfStdIO.h>
#include <ImfTestFile.h>
#include <ImfVersion.h>
#include <Imath/half.h>

#include <stb_image_write.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <new>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace ffxdof::io {
namespace {

namespace fs = std::filesystem;

// Larger images than this are rejected before allocating, so a corrupt header that claims an
// enormous data window gives an error instead of exhausting memory. kMaxSide is the effect's own
// limit (FFX_DOF_MAX_RESOLUTION).
constexpr int64_t kMaxSide = 16384;
constexpr uint64_t kMaxPixels = uint64_t(1) << 28;

std::string boxText(const Imath::Box2i& box) {
    return "(" + std::to_string(box.min.x) + ", " + std::to_string(box.min.y) + ")-(" + std::to_string(box.max.x) +
           ", " + std::to_string(box.max.y) + ")";
}

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw IoError(path + ": " + what); }

std::string joinNames(const std::vector<std::string>& names) {
    if (names.empty()) return "(none)";
    std::string joined;
    for (const std::string& name : names) {
        if (!joined.empty()) joined += ", ";
        joined += name;
    }
    return joined;
}

void checkReadable(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) fail(path, "file not found");
    if (fs::is_directory(path, ec)) fail(path, "is a directory, not an image file");
    std::ifstream file(path, std::ios::binary);
    if (!file) fail(path, std::string("cannot open for reading: ") + std::strerror(errno));
    char magic[4] = {};
    file.read(magic, 4);
    if (file.gcount() != 4 || !Imf::isImfMagic(magic)) fail(path, "not an OpenEXR file (bad magic number)");
}

// Runs an OpenEXR operation, turning the library's exceptions into IoError with the file named.
template <typename Result>
Result guardExr(const std::string& path, const std::function<Result()>& operation) {
    try {
        return operation();
    } catch (const IoError&) {
        throw;
    } catch (const std::bad_alloc&) {
        fail(path, "out of memory while reading (corrupt header?)");
    } catch (const std::exception& error) {
        fail(path, std::string("corrupt or unreadable OpenEXR file: ") + error.what());
    }
}

struct ChannelLocation {
    int part = -1;
    std::string name;
};

std::vector<std::string> channelNames(const Imf::MultiPartInputFile& file) {
    std::vector<std::string> names;
    for (int part = 0; part < file.parts(); ++part) {
        const Imf::ChannelList& channels = file.header(part).channels();
        for (auto it = channels.begin(); it != channels.end(); ++it) names.emplace_back(it.name());
    }
    return names;
}

ChannelLocation findChannel(const Imf::MultiPartInputFile& file, const std::string& name) {
    for (int part = 0; part < file.parts(); ++part) {
        if (file.header(part).channels().findChannel(name)) return {part, name};
    }
    return {};
}

void checkPartReadable(const std::string& path, const Imf::Header& header) {
    if (header.hasType() && (header.type() == Imf::DEEPSCANLINE || header.type() == Imf::DEEPTILE)) {
        fail(path, "deep OpenEXR images are not supported");
    }
}

// Reads the given channels of one part as floats into an interleaved buffer of `stride` floats per
// pixel, channel i at offset i. Missing channels (empty name) keep the fill value.
void readPartChannels(const std::string& path, Imf::MultiPartInputFile& file, int part,
                      const std::vector<std::string>& names, uint32_t stride, float fill, uint32_t& width,
                      uint32_t& height, std::vector<float>& pixels) {
    const Imf::Header& header = file.header(part);
    checkPartReadable(path, header);
    const Imath::Box2i window = header.dataWindow();
    const Imath::Box2i display = header.displayWindow();
    // Pixels are stored from the data window's corner; the tools align images by their first pixel.
    // A data window that is not the display window (overscan, a crop) would silently shift this image
    // against another one, so it is refused rather than guessed.
    if (window != display) {
        fail(path, "the data window " + boxText(window) + " differs from the display window " + boxText(display) +
                       "; only images whose data window is the display window are supported (crop or pad it)");
    }
    // Every size check uses the header alone, before any pixel memory is allocated.
    const int64_t w = int64_t(window.max.x) - window.min.x + 1;
    const int64_t h = int64_t(window.max.y) - window.min.y + 1;
    if (w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide || uint64_t(w) * uint64_t(h) > kMaxPixels) {
        fail(path, "the header claims " + std::to_string(w) + "x" + std::to_string(h) +
                       " pixels; width and height must be 1 to " + std::to_string(kMaxSide));
    }
    Imf::InputPart input(file, part);
    // A header that claims more pixels than the file holds (a truncated or doctored file) is refused
    // from the offset table, before allocating width x height pixels for data that is not there.
    if (!input.isComplete()) {
        fail(path, "the file is truncated or incomplete: it holds fewer pixels than its header claims (" +
                       std::to_string(w) + "x" + std::to_string(h) + ")");
    }
    width = uint32_t(w);
    height = uint32_t(h);
    pixels.assign(size_t(w) * size_t(h) * stride, fill);
    Imf::FrameBuffer frameBuffer;
    for (size_t i = 0; i < names.size(); ++i) {
        if (names[i].empty()) continue;
        const Imf::Channel* channel = header.channels().findChannel(names[i]);
        if (channel->xSampling != 1 || channel->ySampling != 1) {
            fail(path, "channel " + names[i] + " is subsampled, which is not supported");
        }
        frameBuffer.insert(names[i], Imf::Slice::Make(Imf::FLOAT, pixels.data() + i, window, sizeof(float) * stride,
                                                      sizeof(float) * stride * size_t(w)));
    }
    input.setFrameBuffer(frameBuffer);
    input.readPixels(window.min.y, window.max.y);
}

std::string layerChannel(const std::string& layerPrefix, const char* channel) {
    return layerPrefix.empty() ? std::string(channel) : layerPrefix + "." + channel;
}

// ---- writing ------------------------------------------------------------------------------------

[[noreturn]] void failWrite(const std::string& path, const std::string& reason) {
    throw IoError("cannot write " + path + ": " + reason);
}

// Where an output really goes. A symbolic link is followed to the file it names, which is replaced;
// the link itself stays (the policy documented in docs/cli.md).
std::string resolveOutputPath(const std::string& path) {
    fs::path current(path);
    for (int level = 0; level < 40; ++level) {
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(current, ec)) || ec) return current.string();
        const fs::path target = fs::read_symlink(current, ec);
        if (ec) failWrite(path, "cannot read the symbolic link: " + ec.message());
        current = target.is_absolute() ? target : current.parent_path() / target;
    }
    failWrite(path, "too many levels of symbolic links");
}

// Test hook: with FFX_DOF_TEST_WRITE_FAILS_AFTER_BYTES=N in the environment every output file fails
// with ENOSPC once N bytes of it are written, so tests can check what a disk filling up midway leaves
// behind (the old file unchanged, no temporary file) where no small file system can be mounted.
int64_t injectedWriteLimit() {
    const char* text = std::getenv("FFX_DOF_TEST_WRITE_FAILS_AFTER_BYTES");
    if (text == nullptr || *text == '\0') return -1;
    char* end = nullptr;
    const long long limit = std::strtoll(text, &end, 10);
    return (*end == '\0' && limit >= 0) ? int64_t(limit) : -1;
}

// A temporary file next to the destination (next to a symbolic link's target), written with POSIX
// calls so every failure carries its errno. commit() makes it durable and renames it over the
// destination; otherwise it is removed on destruction and the destination is never touched.
class TempFile {
public:
    explicit TempFile(const std::string& destination, IfExists ifExists = IfExists::Replace)
        : requested_(destination), destination_(resolveOutputPath(destination)), ifExists_(ifExists) {
        static std::atomic<unsigned> counter{0};
        const fs::path target(destination_);
        const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
        std::error_code ec;
        if (!fs::is_directory(directory, ec))
            failWrite(requested_, "directory " + directory.string() + " does not exist");
        if (fs::is_directory(target, ec)) failWrite(requested_, "it is a directory");
        struct stat existing {};
        const bool replacing = ::stat(destination_.c_str(), &existing) == 0;
        if (replacing && ifExists_ == IfExists::Replace && !(existing.st_mode & S_IWUSR)) {
            // rename() would replace it regardless of its mode (only the folder's mode counts), so a
            // file marked read-only is refused here rather than silently replaced.
            char mode[8];
            std::snprintf(mode, sizeof(mode), "%04o", unsigned(existing.st_mode & 07777));
            failWrite(requested_, std::string("the existing file is read-only (mode ") + mode +
                                      "); make it writable or remove it to replace it");
        }
        path_ = (directory / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()) + "_" +
                              std::to_string(counter++)))
                    .string();
        fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd_ < 0) {
            failWrite(requested_, "cannot create a file in " + directory.string() + ": " + std::strerror(errno));
        }
        // The replacement keeps the mode of the file it replaces (a new file gets 0666 less the umask).
        if (replacing && ::fchmod(fd_, existing.st_mode & 07777) != 0) {
            failWrite(requested_, std::string("cannot set the mode of the new file: ") + std::strerror(errno));
        }
        writeLimit_ = injectedWriteLimit();
    }
    ~TempFile() {
        if (fd_ >= 0) ::close(fd_);
        if (!committed_) ::unlink(path_.c_str());
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;

    const std::string& path() const { return path_; }
    const std::string& requestedPath() const { return requested_; }

    void write(const char* data, size_t size) {
        while (size > 0) {
            size_t chunk = size;
            if (writeLimit_ >= 0) {
                if (bytesWritten_ >= uint64_t(writeLimit_)) {
                    failWrite(requested_, std::string(std::strerror(ENOSPC)) +
                                              " (injected by FFX_DOF_TEST_WRITE_FAILS_AFTER_BYTES)");
                }
                chunk = std::min<uint64_t>(chunk, uint64_t(writeLimit_) - bytesWritten_);
            }
            const ssize_t written = ::write(fd_, data, chunk);
            if (written < 0) {
                if (errno == EINTR) continue;
                failWrite(requested_, std::strerror(errno));
            }
            data += written;
            size -= size_t(written);
            bytesWritten_ += uint64_t(written);
        }
    }
    void seek(uint64_t position) {
        if (::lseek(fd_, off_t(position), SEEK_SET) < 0) failWrite(requested_, std::strerror(errno));
    }

    // Returns false (the temporary file removed, the destination untouched) when ifExists is Keep and
    // the destination exists by now.
    bool commit() {
        // A full disk may only show at fsync or close (delayed allocation, network file systems).
        if (::fsync(fd_) != 0) failWrite(requested_, std::strerror(errno));
        const int fd = fd_;
        fd_ = -1;
        if (::close(fd) != 0) failWrite(requested_, std::strerror(errno));
        if (ifExists_ == IfExists::Keep) return commitNoReplace();
        if (::rename(path_.c_str(), destination_.c_str()) != 0) {
            failWrite(requested_, std::string("cannot replace the file: ") + std::strerror(errno));
        }
        committed_ = true;
        return true;
    }

private:
    // Atomic create-if-absent: renameat2(RENAME_NOREPLACE) where the file system has it (ext4, xfs,
    // btrfs, tmpfs), otherwise link() + unlink() (NFS, older kernels): both fail with EEXIST instead of
    // replacing a file another process landed first, and neither ever shows a partial file.
    // Test hook: FFX_DOF_TEST_NO_RENAMEAT2=1 takes the link() path, as on a file system without renameat2.
    bool commitNoReplace() {
        const char* noRenameat2 = std::getenv("FFX_DOF_TEST_NO_RENAMEAT2");
        if (noRenameat2 != nullptr && *noRenameat2 != '\0') {
            errno = EINVAL;
        } else if (::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, destination_.c_str(), RENAME_NOREPLACE) == 0) {
            committed_ = true;
            return true;
        }
        if (errno == EEXIST) return false;
        if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) {
            failWrite(requested_, std::string("cannot create the file: ") + std::strerror(errno));
        }
        if (::link(path_.c_str(), destination_.c_str()) != 0) {
            if (errno == EEXIST) return false;
            failWrite(requested_, std::string("cannot create the file: ") + std::strerror(errno));
        }
        return true;  // the temporary name is unlinked by the destructor (committed_ stays false)
    }

    std::string requested_;    // the path as given, for messages
    std::string destination_;  // the file that is replaced: requested_ with symbolic links followed
    std::string path_;
    int fd_ = -1;
    IfExists ifExists_ = IfExists::Replace;
    int64_t writeLimit_ = -1;
    uint64_t bytesWritten_ = 0;
    bool committed_ = false;
};

// OpenEXR's output stream on a TempFile: OpenEXR writes the pixels, then seeks back for the offset table.
class TempFileExrStream final : public Imf::OStream {
public:
    explicit TempFileExrStream(TempFile& file) : Imf::OStream(file.path().c_str()), file_(file) {}
    void write(const char c[], int n) override {
        file_.write(c, size_t(n));
        position_ += uint64_t(n);
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override {
        file_.seek(position);
        position_ = position;
    }

private:
    TempFile& file_;
    uint64_t position_ = 0;
};

void checkImage(const std::string& path, uint32_t width, uint32_t height, size_t values, size_t channels) {
    if (width == 0 || height == 0) fail(path, "cannot write an empty image");
    if (values != size_t(width) * height * channels) {
        fail(path, "image holds " + std::to_string(values) + " values, expected " +
                       std::to_string(size_t(width) * height * channels));
    }
}

}  // namespace

struct ExrKeptLayers::Impl {
    struct Channel {
        std::string name;
        Imf::Channel channel;
        std::vector<char> bytes;  // width * height values of the channel's own type
    };
    uint32_t width = 0, height = 0;
    Imf::Header header;
    std::vector<Channel> channels;
};
ExrKeptLayers::ExrKeptLayers() = default;
ExrKeptLayers::~ExrKeptLayers() = default;
ExrKeptLayers::ExrKeptLayers(ExrKeptLayers&&) noexcept = default;
ExrKeptLayers& ExrKeptLayers::operator=(ExrKeptLayers&&) noexcept = default;
std::vector<std::string> ExrKeptLayers::channelNames() const {
    std::vector<std::string> names;
    if (impl) {
        for (const Impl::Channel& channel : impl->channels) names.push_back(channel.name);
    }
    return names;
}

namespace {

size_t pixelTypeSize(Imf::PixelType type) { return type == Imf::HALF ? 2 : 4; }

// Header attributes that describe the file's structure, not its content: never copied by --keep-layers.
bool isStructuralAttribute(const std::string& name) {
    for (const char* structural : {"channels", "dataWindow", "displayWindow", "compression", "lineOrder", "tiles",
                                   "type", "name", "chunkCount", "version", "view"}) {
        if (name == structural) return true;
    }
    return false;
}

// Writes interleaved float data (channelCount values per pixel) as one EXR part, with the kept layers.
bool writeExrChannels(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& pixels,
                      const std::vector<std::string>& names, ExrPixelType type, IfExists ifExists = IfExists::Replace,
                      const ExrKeptLayers* kept = nullptr) {
    const size_t channelCount = names.size();
    checkImage(path, width, height, pixels.size(), channelCount);
    const ExrKeptLayers::Impl* extra = kept ? kept->impl.get() : nullptr;
    if (extra && (extra->width != width || extra->height != height)) {
        fail(path, "the kept layers are " + std::to_string(extra->width) + "x" + std::to_string(extra->height) +
                       ", the image " + std::to_string(width) + "x" + std::to_string(height));
    }
    TempFile temp(path, ifExists);
    try {
        Imf::Header header{int(width), int(height)};
        if (extra) {
            for (auto it = extra->header.begin(); it != extra->header.end(); ++it) {
                if (!isStructuralAttribute(it.name())) header.insert(it.name(), it.attribute());
            }
        }
        header.compression() = Imf::ZIP_COMPRESSION;
        const Imf::PixelType pixelType = type == ExrPixelType::Half ? Imf::HALF : Imf::FLOAT;
        for (const std::string& name : names) header.channels().insert(name, Imf::Channel(pixelType));
        std::vector<half> halves;
        const char* base = reinterpret_cast<const char*>(pixels.data());
        size_t elementSize = sizeof(float);
        if (type == ExrPixelType::Half) {
            halves.assign(pixels.begin(), pixels.end());
            base = reinterpret_cast<const char*>(halves.data());
            elementSize = sizeof(half);
        }
        Imf::FrameBuffer frameBuffer;
        for (size_t i = 0; i < channelCount; ++i) {
            frameBuffer.insert(names[i], Imf::Slice(pixelType, const_cast<char*>(base + i * elementSize),
                                                    elementSize * channelCount, elementSize * channelCount * width));
        }
        if (extra) {
            for (const ExrKeptLayers::Impl::Channel& channel : extra->channels) {
                if (header.channels().findChannel(channel.name)) continue;  // the image's own channels win
                header.channels().insert(channel.name, channel.channel);
                const size_t size = pixelTypeSize(channel.channel.type);
                frameBuffer.insert(
                    channel.name,
                    Imf::Slice(channel.channel.type, const_cast<char*>(channel.bytes.data()), size, size * width));
            }
        }
        TempFileExrStream exrStream(temp);
        Imf::OutputFile output(exrStream, header);
        output.setFrameBuffer(frameBuffer);
        output.writePixels(int(height));
    } catch (const IoError&) {
        throw;
    } catch (const std::bad_alloc&) {
        failWrite(path, "out of memory while encoding");
    } catch (const std::exception& error) {
        failWrite(path, error.what());
    }
    return temp.commit();
}

uint8_t encodeSrgb8(float linear) {
    if (!(linear > 0.0f)) return 0;  // also maps NaN to 0
    if (linear >= 1.0f) return 255;
    const float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(encoded * 255.0f));
}

uint8_t encodeLinear8(float value) {
    if (!(value > 0.0f)) return 0;
    if (value >= 1.0f) return 255;
    return uint8_t(std::lround(value * 255.0f));
}

}  // namespace

ImageRGBA readExrColor(const std::string& path, const std::string& layerPrefix) {
    checkReadable(path);
    return guardExr<ImageRGBA>(path, [&] {
        Imf::MultiPartInputFile file(path.c_str());
        const std::string red = layerChannel(layerPrefix, "R");
        const ChannelLocation location = findChannel(file, red);
        if (location.part < 0) {
            fail(path, "no colour channel " + red + "; channels present: " + joinNames(channelNames(file)));
        }
        const Imf::ChannelList& channels = file.header(location.part).channels();
        std::vector<std::string> names;
        for (const char* channel : {"R", "G", "B", "A"}) {
            const std::string name = layerChannel(layerPrefix, channel);
            if (channels.findChannel(name)) {
                names.push_back(name);
            } else if (std::strcmp(channel, "A") == 0) {
                names.emplace_back();
            } else {
                fail(path, "colour channel " + name +
                               " is missing (need R, G and B); channels present: " + joinNames(channelNames(file)));
            }
        }
        ImageRGBA image;
        readPartChannels(path, file, location.part, names, 4, 1.0f, image.width, image.height, image.pixels);
        // R, G, B are always read; only A keeps the fill value of 1 when absent.
        return image;
    });
}

ImageR readExrChannel(const std::string& path, const std::string& channelName) {
    checkReadable(path);
    return guardExr<ImageR>(path, [&] {
        Imf::MultiPartInputFile file(path.c_str());
        const std::vector<std::string> names = channelNames(file);
        ChannelLocation location;
        if (channelName.empty()) {
            if (names.size() != 1) {
                fail(path, "expected a single-channel file but it has " + std::to_string(names.size()) + " channels (" +
                               joinNames(names) + "); name the channel to read");
            }
            location = {0, names.front()};
        } else {
            location = findChannel(file, channelName);
            if (location.part < 0) {
                fail(path, "no channel named " + channelName + "; channels present: " + joinNames(names));
            }
        }
        ImageR image;
        readPartChannels(path, file, location.part, {location.name}, 1, 0.0f, image.width, image.height, image.pixels);
        return image;
    });
}

std::vector<std::string> listExrChannels(const std::string& path) {
    checkReadable(path);
    return guardExr<std::vector<std::string>>(path, [&] {
        Imf::MultiPartInputFile file(path.c_str());
        return channelNames(file);
    });
}

ExrProbe probeExr(const std::string& path) {
    checkReadable(path);
    return guardExr<ExrProbe>(path, [&] {
        Imf::MultiPartInputFile file(path.c_str());
        ExrProbe probe;
        const Imath::Box2i window = file.header(0).dataWindow();
        probe.width = uint32_t(std::max(0, window.max.x - window.min.x + 1));
        probe.height = uint32_t(std::max(0, window.max.y - window.min.y + 1));
        probe.channels = channelNames(file);
        probe.complete = true;
        for (int part = 0; part < file.parts(); ++part) probe.complete = probe.complete && file.partComplete(part);
        // The offset table sits at the start, so a file cut short still has a whole one: every chunk of
        // the first part is decoded too (into one row of one channel), which fails on a missing or
        // damaged chunk.
        const Imf::Header& header = file.header(0);
        if (probe.complete && header.channels().begin() != header.channels().end() &&
            (!header.hasType() || header.type() == Imf::SCANLINEIMAGE)) {
            try {
                Imf::InputPart input(file, 0);
                std::vector<float> row(size_t(probe.width) + 1);
                Imf::FrameBuffer frameBuffer;
                frameBuffer.insert(
                    header.channels().begin().name(),
                    Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(row.data() - window.min.x), sizeof(float), 0));
                input.setFrameBuffer(frameBuffer);
                input.readPixels(window.min.y, window.max.y);
            } catch (const std::exception&) {
                probe.complete = false;
            }
        }
        return probe;
    });
}

ExrKeptLayers readExrKeptLayers(const std::string& path, const std::string& layerPrefix) {
    checkReadable(path);
    return guardExr<ExrKeptLayers>(path, [&] {
        Imf::MultiPartInputFile file(path.c_str());
        const ChannelLocation location = findChannel(file, layerChannel(layerPrefix, "R"));
        ExrKeptLayers kept;
        kept.impl = std::make_unique<ExrKeptLayers::Impl>();
        if (location.part < 0) return kept;  // the colour reader reports the missing layer
        const Imf::Header& header = file.header(location.part);
        checkPartReadable(path, header);
        const Imath::Box2i window = header.dataWindow();
        const int64_t w = int64_t(window.max.x) - window.min.x + 1, h = int64_t(window.max.y) - window.min.y + 1;
        if (window != header.displayWindow() || w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide) {
            fail(path, "the data window " + boxText(window) + " is not the display window or too large");
        }
        Imf::InputPart input(file, location.part);
        if (!input.isComplete()) fail(path, "the file is truncated or incomplete");
        kept.impl->width = uint32_t(w);
        kept.impl->height = uint32_t(h);
        kept.impl->header = header;
        Imf::FrameBuffer frameBuffer;
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
            const std::string name = it.name();
            bool isColor = false;
            for (const char* channel : {"R", "G", "B", "A"})
                isColor = isColor || name == layerChannel(layerPrefix, channel);
            if (isColor) continue;
            if (it.channel().xSampling != 1 || it.channel().ySampling != 1) {
                fail(path, "channel " + name + " is subsampled, which --keep-layers does not support");
            }
            kept.impl->channels.push_back({name, it.channel(), {}});
        }
        for (ExrKeptLayers::Impl::Channel& channel : kept.impl->channels) {
            const size_t size = pixelTypeSize(channel.channel.type);
            channel.bytes.assign(size_t(w) * size_t(h) * size, 0);
            frameBuffer.insert(channel.name, Imf::Slice::Make(channel.channel.type, channel.bytes.data(), window, size,
                                                              size * size_t(w)));
        }
        if (!kept.impl->channels.empty()) {
            input.setFrameBuffer(frameBuffer);
            input.readPixels(window.min.y, window.max.y);
        }
        return kept;
    });
}

bool writeExr(const std::string& path, const ImageRGBA& image, const ExrWriteOptions& options) {
    std::vector<std::string> names;
    for (const char* channel : {"R", "G", "B", "A"}) names.push_back(layerChannel(options.layerPrefix, channel));
    return writeExrChannels(path, image.width, image.height, image.pixels, names, options.type, options.ifExists,
                            options.kept);
}

void writeExr(const std::string& path, const ImageRGBA& image, ExrPixelType type) {
    writeExrChannels(path, image.width, image.height, image.pixels, {"R", "G", "B", "A"}, type);
}

void writeExr(const std::string& path, const ImageR& image, ExrPixelType type, const std::string& channelName) {
    if (channelName.empty()) fail(path, "empty channel name");
    writeExrChannels(path, image.width, image.height, image.pixels, {channelName}, type);
}

void writePng(const std::string& path, const ImageRGBA& image, bool withAlpha) {
    checkImage(path, image.width, image.height, image.pixels.size(), 4);
    if (image.width > (1u << 24) / 4 || image.height > (1u << 24)) fail(path, "image too large for PNG");
    const int components = withAlpha ? 4 : 3;
    std::vector<uint8_t> bytes(size_t(image.width) * image.height * components);
    for (size_t pixel = 0; pixel < size_t(image.width) * image.height; ++pixel) {
        const float* source = &image.pixels[pixel * 4];
        uint8_t* target = &bytes[pixel * components];
        for (int c = 0; c < 3; ++c) target[c] = encodeSrgb8(source[c]);
        if (withAlpha) target[3] = encodeLinear8(source[3]);
    }
    // stb_image_write encodes into memory through a callback, so the bytes go through TempFile like
    // every other output (and no longjmp error handling as with libpng crosses C++ frames).
    std::vector<uint8_t> encoded;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<uint8_t>*>(context);
        const auto* begin = static_cast<const uint8_t*>(data);
        out->insert(out->end(), begin, begin + size);
    };
    if (!stbi_write_png_to_func(append, &encoded, int(image.width), int(image.height), components, bytes.data(),
                                int(image.width) * components)) {
        fail(path, "PNG encoding failed");
    }
    writeFileReplacing(path, [&](std::ostream& stream) {
        stream.write(reinterpret_cast<const char*>(encoded.data()), std::streamsize(encoded.size()));
    });
}

void writeFileReplacing(const std::string& path, const std::function<void(std::ostream&)>& writer) {
    TempFile temp(path);
    // The content is made in memory first, so every byte reaches the file through TempFile::write and
    // its error reporting.
    std::ostringstream content;
    writer(content);
    if (!content) failWrite(path, "the content could not be produced");
    const std::string bytes = content.str();
    temp.write(bytes.data(), bytes.size());
    temp.commit();
}

bool hasExtension(const std::string& path, const std::string& extension) {
    if (path.size() < extension.size()) return false;
    return std::equal(extension.rbegin(), extension.rend(), path.rbegin(),
                      [](char a, char b) { return std::tolower((unsigned char)a) == std::tolower((unsigned char)b); });
}

void writeImage(const std::string& path, const ImageRGBA& image, ExrPixelType exrType) {
    if (hasExtension(path, ".exr")) {
        writeExr(path, image, exrType);
    } else if (hasExtension(path, ".png")) {
        writePng(path, image, false);
    } else {
        fail(path, "unknown output format (use a .exr or .png extension)");
    }
}

}  // namespace ffxdof::io
