// Frame sequences for `ffx-dof apply`: file-name patterns (shot.####.exr, shot.%04d.exr), frame
// lists (--frames 1001-1100x2,1200), a farm task's share of them (--chunk I/N), and the camera track
// (a lens per frame from a JSON or CSV file). No Vulkan here: unit-tested in tests/cli.
#pragma once

#include "lens.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ffxdof::cli {

// A file name with one frame-number field: a run of '#' (one digit each, zero-padded to that many
// digits) or printf's %d / %0Nd. A name without a field is a constant (the same file every frame).
class FramePattern {
public:
    FramePattern() = default;
    // Throws CliError(Usage) naming `option` for two fields or a malformed %-field.
    FramePattern(const std::string& text, const std::string& option);
    bool hasField() const { return hasField_; }
    const std::string& text() const { return text_; }
    // The name of a frame (frame >= 0); a constant pattern returns its text.
    std::string path(int64_t frame) const;

private:
    std::string text_, prefix_, suffix_;
    int digits_ = 0;
    bool hasField_ = false;
};

// "A-B" (A to B), "A-BxS" (every S-th from A), "A" (one frame), and comma-separated lists of them, in
// the order given, without repeats. Frames are 0 to 999999999. Throws CliError(Usage) for malformed
// text and an empty list, CliError(InvalidValue) for B < A or a step of 0.
std::vector<int64_t> parseFrameList(const std::string& text);

// "I/N": the I-th (1 to N) of N contiguous shares of the frames, sizes differing by at most one, so N
// farm tasks given I = 1..N each run their share of the same --frames. Throws CliError(Usage) for
// malformed text and CliError(InvalidValue) for I outside 1..N.
struct Chunk {
    uint32_t index = 1, count = 1;
};
Chunk parseChunk(const std::string& text);
std::vector<int64_t> chunkOf(const std::vector<int64_t>& frames, const Chunk& chunk);

// The lens of each frame from a camera track file. JSON: an array of objects, or {"frames": [...]};
// CSV: a header line naming the columns, then one line per frame. Keys / columns (any order, case and
// '_' / '-' ignored): frame (required), focus (metres), fstop or aperture_radius (metres),
// focal_length (mm), sensor_width (mm). A value missing from the track comes from the command line.
struct CameraTrackEntry {
    std::optional<double> focusMetres, fNumber, apertureRadiusMetres, focalLengthMm, sensorWidthMm;
};
using CameraTrack = std::map<int64_t, CameraTrackEntry>;
// Throws CliError(InputFile) for a missing or malformed file (the message names the line or entry).
CameraTrack readCameraTrack(const std::string& path);
// The lens of a frame: the command line's, overridden by the track's values for that frame. Throws
// CliError(InvalidValue) when the track has no entry for the frame.
LensSettings lensForFrame(const LensSettings& commandLine, const CameraTrack& track, int64_t frame,
                          const std::string& trackPath);

}  // namespace ffxdof::cli
