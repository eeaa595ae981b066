#include "sequence.h"

#include "cli_error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

namespace ffxdof::cli {
namespace {

constexpr int64_t kLargestFrame = 999999999;

// Digits only, at most 9 of them (frames are 0 to 999999999).
bool parseFrameNumber(const std::string& text, int64_t& value) {
    if (text.empty() || text.size() > 9 ||
        !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        return false;
    }
    value = std::stoll(text);
    return true;
}

std::string normaliseKey(const std::string& key) {
    std::string normal;
    for (char c : key) {
        if (c == '_' || c == '-' || c == ' ') continue;
        normal += char(std::tolower(static_cast<unsigned char>(c)));
    }
    return normal;
}

// Sets the entry's field named by a (normalised) key; returns false for an unknown key.
bool setTrackValue(CameraTrackEntry& entry, const std::string& key, double value) {
    if (key == "focus" || key == "focusdistance") {
        entry.focusMetres = value;
    } else if (key == "fstop" || key == "fnumber") {
        entry.fNumber = value;
    } else if (key == "apertureradius") {
        entry.apertureRadiusMetres = value;
    } else if (key == "focallength") {
        entry.focalLengthMm = value;
    } else if (key == "sensorwidth") {
        entry.sensorWidthMm = value;
    } else {
        return false;
    }
    return true;
}

[[noreturn]] void trackError(const std::string& path, const std::string& what) {
    throw CliError(ExitCode::InputFile, path + ": " + what);
}

bool parseNumber(const std::string& text, double& value) {
    if (text.empty()) return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return *end == '\0';
}

void addEntry(CameraTrack& track, const std::string& path, int64_t frame, const CameraTrackEntry& entry,
              const std::string& where) {
    if (entry.fNumber && entry.apertureRadiusMetres) {
        trackError(path, where + " gives both fstop and aperture_radius");
    }
    if (!track.emplace(frame, entry).second) trackError(path, where + ": frame " + std::to_string(frame) + " repeats");
}

CameraTrack readJsonTrack(const std::string& path, const std::string& text) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& error) {
        trackError(path, std::string("not valid JSON: ") + error.what());
    }
    const nlohmann::json* entries = &document;
    if (document.is_object() && document.contains("frames")) entries = &document["frames"];
    if (!entries->is_array()) trackError(path, "expected an array of frames, or {\"frames\": [...]}");
    CameraTrack track;
    for (size_t i = 0; i < entries->size(); ++i) {
        const nlohmann::json& item = (*entries)[i];
        const std::string where = "entry " + std::to_string(i);
        if (!item.is_object()) trackError(path, where + " is not an object");
        CameraTrackEntry entry;
        int64_t frame = -1;
        for (auto it = item.begin(); it != item.end(); ++it) {
            const std::string key = normaliseKey(it.key());
            if (!it.value().is_number()) trackError(path, where + ": " + it.key() + " is not a number");
            if (key == "frame") {
                if (!it.value().is_number_integer() || it.value().get<int64_t>() < 0 ||
                    it.value().get<int64_t>() > kLargestFrame) {
                    trackError(path, where + ": frame must be a whole number, 0 to 999999999");
                }
                frame = it.value().get<int64_t>();
            } else if (!setTrackValue(entry, key, it.value().get<double>())) {
                trackError(path, where + ": unknown key " + it.key() +
                                     " (frame, focus, fstop, aperture_radius, focal_length, sensor_width)");
            }
        }
        if (frame < 0) trackError(path, where + " has no frame");
        addEntry(track, path, frame, entry, where);
    }
    return track;
}

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream stream(line);
    while (std::getline(stream, field, ',')) {
        const size_t first = field.find_first_not_of(" \t\r\"");
        const size_t last = field.find_last_not_of(" \t\r\"");
        fields.push_back(first == std::string::npos ? std::string() : field.substr(first, last - first + 1));
    }
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

CameraTrack readCsvTrack(const std::string& path, const std::string& text) {
    std::istringstream stream(text);
    std::string line;
    std::vector<std::string> columns;
    CameraTrack track;
    size_t lineNumber = 0;
    int frameColumn = -1;
    while (std::getline(stream, line)) {
        ++lineNumber;
        if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
        const std::vector<std::string> fields = splitCsvLine(line);
        const std::string where = "line " + std::to_string(lineNumber);
        if (columns.empty()) {
            CameraTrackEntry probe;
            for (size_t i = 0; i < fields.size(); ++i) {
                const std::string key = normaliseKey(fields[i]);
                if (key == "frame") {
                    frameColumn = int(i);
                } else if (!setTrackValue(probe, key, 0.0)) {
                    trackError(path, where + ": unknown column " + fields[i] +
                                         " (frame, focus, fstop, aperture_radius, focal_length, sensor_width)");
                }
                columns.push_back(key);
            }
            if (frameColumn < 0) trackError(path, "the header line names no frame column");
            continue;
        }
        if (fields.size() != columns.size()) {
            trackError(path, where + " has " + std::to_string(fields.size()) + " fields, the header " +
                                 std::to_string(columns.size()));
        }
        CameraTrackEntry entry;
        int64_t frame = 0;
        for (size_t i = 0; i < fields.size(); ++i) {
            if (int(i) == frameColumn) {
                if (!parseFrameNumber(fields[i], frame)) {
                    trackError(path, where + ": frame must be a whole number, 0 to 999999999, got '" + fields[i] + "'");
                }
                continue;
            }
            if (fields[i].empty()) continue;  // from the command line
            double value = 0.0;
            if (!parseNumber(fields[i], value)) {
                trackError(path, where + ": " + columns[i] + " is not a number: '" + fields[i] + "'");
            }
            setTrackValue(entry, columns[i], value);
        }
        addEntry(track, path, frame, entry, where);
    }
    if (columns.empty()) trackError(path, "empty camera track");
    return track;
}

}  // namespace

FramePattern::FramePattern(const std::string& text, const std::string& option) : text_(text) {
    const size_t hash = text.find('#');
    const size_t percent = text.find('%');
    if (hash != std::string::npos) {
        const size_t end = text.find_first_not_of('#', hash);
        const size_t stop = end == std::string::npos ? text.size() : end;
        if (text.find('#', stop) != std::string::npos || percent != std::string::npos) {
            throw CliError(ExitCode::Usage, option + " " + text + ": more than one frame-number field");
        }
        prefix_ = text.substr(0, hash);
        suffix_ = text.substr(stop);
        digits_ = int(stop - hash);
        hasField_ = true;
    } else if (percent != std::string::npos) {
        // %d or %0Nd (N of 1 or 2 digits); %% is not supported.
        size_t i = percent + 1;
        std::string width;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') width += text[i++];
        if (i >= text.size() || text[i] != 'd' || (!width.empty() && (width[0] != '0' || width.size() > 3)) ||
            text.find('%', i) != std::string::npos) {
            throw CliError(ExitCode::Usage,
                           option + " " + text + ": a frame-number field is #### or %d / %0Nd, once per name");
        }
        prefix_ = text.substr(0, percent);
        suffix_ = text.substr(i + 1);
        digits_ = width.empty() ? 1 : std::max(1, std::atoi(width.c_str()));
        hasField_ = true;
    }
}

std::string FramePattern::path(int64_t frame) const {
    if (!hasField_) return text_;
    char digits[32];
    std::snprintf(digits, sizeof(digits), "%0*lld", digits_, static_cast<long long>(frame));
    return prefix_ + digits + suffix_;
}

std::vector<int64_t> parseFrameList(const std::string& text) {
    const auto malformed = [&]() {
        return CliError(ExitCode::Usage,
                        "--frames: expected FIRST-LAST, FIRST-LASTxSTEP or FRAME, comma-separated "
                        "(e.g. 1001-1100, 1001-1100x2), got '" +
                            text + "'");
    };
    std::vector<int64_t> frames;
    std::set<int64_t> seen;
    std::string item;
    std::istringstream stream(text);
    if (text.empty() || text.back() == ',') throw malformed();
    while (std::getline(stream, item, ',')) {
        int64_t first = 0, last = 0, step = 1;
        const size_t dash = item.find('-');
        if (dash == std::string::npos) {
            if (!parseFrameNumber(item, first)) throw malformed();
            last = first;
        } else {
            const size_t x = item.find('x', dash);
            if (!parseFrameNumber(item.substr(0, dash), first) ||
                !parseFrameNumber(item.substr(dash + 1, x == std::string::npos ? std::string::npos : x - dash - 1),
                                  last) ||
                (x != std::string::npos && !parseFrameNumber(item.substr(x + 1), step))) {
                throw malformed();
            }
        }
        if (last < first) {
            throw CliError(ExitCode::InvalidValue, "--frames " + item + ": the last frame is before the first");
        }
        if (step < 1) throw CliError(ExitCode::InvalidValue, "--frames " + item + ": the step must be 1 or more");
        for (int64_t frame = first; frame <= last; frame += step) {
            if (seen.insert(frame).second) frames.push_back(frame);
        }
    }
    if (frames.empty()) throw malformed();
    return frames;
}

Chunk parseChunk(const std::string& text) {
    const size_t slash = text.find('/');
    int64_t index = 0, count = 0;
    if (slash == std::string::npos || !parseFrameNumber(text.substr(0, slash), index) ||
        !parseFrameNumber(text.substr(slash + 1), count)) {
        throw CliError(ExitCode::Usage, "--chunk: expected I/N (the I-th of N shares, 1 to N), got '" + text + "'");
    }
    if (count < 1 || index < 1 || index > count) {
        throw CliError(ExitCode::InvalidValue, "--chunk " + text + ": I must be 1 to N");
    }
    return {uint32_t(index), uint32_t(count)};
}

std::vector<int64_t> chunkOf(const std::vector<int64_t>& frames, const Chunk& chunk) {
    const size_t size = frames.size();
    const size_t begin = size * (chunk.index - 1) / chunk.count;
    const size_t end = size * chunk.index / chunk.count;
    return std::vector<int64_t>(frames.begin() + std::ptrdiff_t(begin), frames.begin() + std::ptrdiff_t(end));
}

CameraTrack readCameraTrack(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) trackError(path, std::string("cannot open the camera track: ") + std::strerror(errno));
    std::ostringstream content;
    content << file.rdbuf();
    const std::string text = content.str();
    const size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && (text[first] == '[' || text[first] == '{')) return readJsonTrack(path, text);
    return readCsvTrack(path, text);
}

LensSettings lensForFrame(const LensSettings& commandLine, const CameraTrack& track, int64_t frame,
                          const std::string& trackPath) {
    if (track.empty()) return commandLine;
    const auto found = track.find(frame);
    if (found == track.end()) {
        throw CliError(ExitCode::InvalidValue, trackPath + " has no entry for frame " + std::to_string(frame) +
                                                   " (it has frames " + std::to_string(track.begin()->first) + " to " +
                                                   std::to_string(track.rbegin()->first) + ")");
    }
    const CameraTrackEntry& entry = found->second;
    LensSettings lens = commandLine;
    if (entry.focusMetres) lens.focusMetres = *entry.focusMetres;
    if (entry.focalLengthMm) lens.focalLengthMm = *entry.focalLengthMm;
    if (entry.sensorWidthMm) lens.sensorWidthMm = *entry.sensorWidthMm;
    if (entry.fNumber) {
        lens.fNumber = entry.fNumber;
        lens.apertureRadiusMetres.reset();
    } else if (entry.apertureRadiusMetres) {
        lens.apertureRadiusMetres = entry.apertureRadiusMetres;
        lens.fNumber.reset();
    }
    return lens;
}

}  // namespace ffxdof::cli
