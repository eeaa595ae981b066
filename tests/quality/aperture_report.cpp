// Regenerates docs/images/aperture/*.png and the generated figures of docs/aperture.md (between the
// markers <!-- aperture-figures:begin --> and <!-- aperture-figures:end -->; the rest of the page is
// written by hand) from the aperture gates:
//   cmake --build build/default --target ffx_dof_aperture_report
// or run ffx_dof_aperture_report_tool --docs <repo>/docs directly. Without --docs it prints the
// figures only.
#include "aperture_gates.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>

using namespace ffxdof;

namespace {

const char* const kBeginMarker = "<!-- aperture-figures:begin -->";
const char* const kEndMarker = "<!-- aperture-figures:end -->";
// The scene of the pictures (the figures cover both highlight scenes): the larger discs.
const char* const kPictureScene = "mid-lights";

std::string number(double value, const char* format) {
    if (std::isnan(value)) return "n/a";
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

const char* verdict(bool ok) { return ok ? "pass" : "**FAIL**"; }

// The panels side by side, `gap` px of grey between them.
io::ImageRGBA sideBySide(const std::vector<io::ImageRGBA>& panels, uint32_t gap = 4) {
    uint32_t width = 0, height = 0;
    for (const io::ImageRGBA& panel : panels) {
        width += panel.width;
        height = std::max(height, panel.height);
    }
    width += gap * uint32_t(panels.size() - 1);
    io::ImageRGBA result(width, height);
    for (size_t i = 0; i < result.pixels.size(); ++i) result.pixels[i] = i % 4 == 3 ? 1.0f : 0.5f;
    uint32_t left = 0;
    for (const io::ImageRGBA& panel : panels) {
        for (uint32_t y = 0; y < panel.height; ++y) {
            for (uint32_t x = 0; x < panel.width; ++x) std::copy_n(panel.at(x, y), 4, result.at(left + x, y));
        }
        left += panel.width + gap;
    }
    return result;
}

// A size x size crop centred on (cx, cy), divided by `level` then times 0.8, enlarged `zoom` times.
io::ImageRGBA cropAround(const io::ImageRGBA& image, uint32_t cx, uint32_t cy, uint32_t size, double level,
                         uint32_t zoom) {
    io::ImageRGBA result(size * zoom, size * zoom);
    const int left = int(cx) - int(size / 2), top = int(cy) - int(size / 2);
    const float scale = level > 0.0 ? float(0.8 / level) : 1.0f;
    for (uint32_t y = 0; y < result.height; ++y) {
        for (uint32_t x = 0; x < result.width; ++x) {
            const int sx = left + int(x / zoom), sy = top + int(y / zoom);
            float* out = result.at(x, y);
            out[3] = 1.0f;
            if (sx < 0 || sy < 0 || sx >= int(image.width) || sy >= int(image.height)) continue;
            const float* in = image.at(uint32_t(sx), uint32_t(sy));
            for (int c = 0; c < 3; ++c) out[c] = in[c] * scale;
        }
    }
    return result;
}

// The two discs' masks: white where both, orange the truth's only, blue ffx-dof's only.
io::ImageRGBA maskOverlay(const quality::DiscShape& truth, const quality::DiscShape& ours, uint32_t width,
                          uint32_t height) {
    io::ImageRGBA result(width, height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const size_t i = size_t(y) * width + x;
            float* out = result.at(x, y);
            out[3] = 1.0f;
            if (truth.mask[i] && ours.mask[i]) {
                out[0] = out[1] = out[2] = 0.8f;
            } else if (truth.mask[i]) {
                out[0] = 1.0f, out[1] = 0.45f;
            } else if (ours.mask[i]) {
                out[1] = 0.35f, out[2] = 1.0f;
            }
        }
    }
    return result;
}

double seconds(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Replaces the text between the markers of the page (which must hold both, in order).
void replaceBetweenMarkers(const std::filesystem::path& page, const std::string& generated) {
    std::ifstream in(page);
    if (!in) throw std::runtime_error("cannot read " + page.string());
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    const size_t begin = text.find(kBeginMarker), end = text.find(kEndMarker);
    if (begin == std::string::npos || end == std::string::npos || end < begin) {
        throw std::runtime_error(page.string() + " lacks the markers " + kBeginMarker + " ... " + kEndMarker);
    }
    const std::string updated =
        text.substr(0, begin + std::string(kBeginMarker).size()) + "\n" + generated + text.substr(end);
    io::writeFileReplacing(page.string(), [&](std::ostream& out) { out << updated; });
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Regenerates docs/images/aperture/*.png and the figures of docs/aperture.md from the aperture gates."};
    std::string docs;
    app.add_option("--docs", docs, "the docs folder of the repository (without it: print the figures only)")
        ->check(CLI::ExistingDirectory);
    CLI11_PARSE(app, argc, argv);

    try {
        const std::filesystem::path imageDir =
            docs.empty() ? std::filesystem::path() : std::filesystem::path(docs) / "images" / "aperture";
        if (!docs.empty()) std::filesystem::create_directories(imageDir);
        const auto writePng = [&](const std::string& name, const io::ImageRGBA& image) {
            if (!docs.empty()) io::writePng((imageDir / name).string(), image);
        };
        vkrun::Device device;
        std::ostringstream md;
        md << "<!-- Generated by ffx_dof_aperture_report_tool (tests/quality/aperture_report.cpp): edit the tool, "
              "not this part. -->\n\n"
           << "Device: " << device.name() << ".\n\n";

        // ---- points ----
        md << "### Points\n\n"
           << "One point on black, " << quality::kPointWidth << "x" << quality::kPointHeight << ", "
           << quality::kPointLensSamples
           << " lens samples for the truth. Pictures, left to right: input, ffx-dof, truth (each divided by its "
              "own disc level, a 64 px crop enlarged twice), and the two discs' masks (grey: both, orange: the "
              "truth's only, blue: ffx-dof's only).\n\n"
           << "| point | CoC radius | IoU (>= " << number(quality::kPointMinIou, "%.2f")
           << ") | area error (<= " << number(100.0 * quality::kPointMaxAreaError, "%.0f")
           << "%) | vertex angle: ffx-dof, truth, definition"
           << " (ffx-dof - truth <= " << number(quality::kPointMaxVertexAngleDegrees, "%.0f")
           << " deg) | elongation: ffx-dof, truth | long axis: ffx-dof, truth | centroid distance (<= "
           << number(quality::kPointMaxCentroidDistancePixels, "%.0f")
           << " px) | shape: area, orientation | position: IoU, centroid |\n"
           << "|---|---|---|---|---|---|---|---|---|---|\n";
        std::ostringstream pointPictures;
        for (const quality::PointCase& point : quality::pointCases()) {
            const auto start = std::chrono::steady_clock::now();
            const quality::PointResult r = quality::measurePoint(device, point);
            std::printf("%s(%.1f s)\n", r.summary().c_str(), seconds(start));
            const uint32_t crop = 64, zoom = 2;
            const std::string file = "point_" + point.name() + ".png";
            writePng(
                file,
                sideBySide({cropAround(r.render.pinhole.color, point.pixelX, point.pixelY, crop, r.truth.level, zoom),
                            cropAround(r.result.ours, point.pixelX, point.pixelY, crop, r.ours.level, zoom),
                            cropAround(r.render.truth, point.pixelX, point.pixelY, crop, r.truth.level, zoom),
                            cropAround(maskOverlay(r.truth, r.ours, r.render.truth.width, r.render.truth.height),
                                       point.pixelX, point.pixelY, crop, 0.8, zoom)}));
            const bool polygon = point.aperture.shape.bladeCount >= 3;
            // Corners shown next to the definition's (the angles are modulo 360 / N).
            const double definition = quality::expectedVertexDegrees(point);
            const double period = polygon ? 360.0 / point.aperture.shape.bladeCount : 360.0;
            const auto corner = [&](double degrees) {
                return number(definition + quality::wrapDegrees(degrees - definition, period), "%.1f");
            };
            md << "| " << point.name() << " | " << number(std::abs(point.radiusPixels), "%.0f") << " px "
               << (point.nearField() ? "near" : "far") << " | " << number(r.iou, "%.3f") << " | "
               << number(100.0 * r.areaError, "%+.1f") << "% | "
               << (polygon ? corner(r.ours.vertexDegrees) + ", " + corner(r.truth.vertexDegrees) + ", " +
                                 number(definition, "%.1f")
                           : std::string("-"))
               << " | " << number(r.ours.elongation, "%.3f") << ", " << number(r.truth.elongation, "%.3f") << " | "
               << (std::isnan(r.axisDifference)
                       ? std::string("-")
                       : number(r.ours.axisDegrees, "%.1f") + ", " + number(r.truth.axisDegrees, "%.1f") + " deg")
               << " | " << number(r.centroidDistance, "%.2f") << " px | " << verdict(r.shapeOk()) << " | "
               << verdict(r.positionOk()) << " |\n";
            pointPictures << "**" << point.name() << "** (" << point.aperture.title << ", "
                          << (point.nearField() ? "in front of" : "behind") << " the focus)\n\n![" << point.name()
                          << "](images/aperture/" << file << ")\n\n";
        }
        md << "\nThe vertex angle is that of a polygon's corner (y up, counter-clockwise from +x, modulo 360 / N): "
              "the phase of the N-fold moment of the disc's mask over N. The definition's is the blade rotation plus "
              "180 / N, plus 180 degrees in front of the focus. Elongation and long axis come from the mask's second "
              "moments and are compared from an elongation of "
           << number(quality::kPointMinElongation, "%.1f") << " on (to within "
           << number(quality::kPointMaxAxisDegrees, "%.0f") << " degrees and "
           << number(100.0 * quality::kPointMaxElongationError, "%.0f") << "%).\n\n"
           << pointPictures.str();

        // ---- scenes ----
        // Every (scene, aperture) rendered once: the gates' and the pictures' figures are the same runs.
        struct SceneRun {
            quality::SceneRender render;
            quality::GateResult result;
        };
        std::map<std::string, SceneRun> runs;
        const auto run = [&](const std::string& scene, const quality::NamedAperture& aperture) -> const SceneRun& {
            const std::string key = scene + "_" + aperture.name;
            auto found = runs.find(key);
            if (found != runs.end()) return found->second;
            const auto start = std::chrono::steady_clock::now();
            SceneRun r;
            r.render =
                quality::renderScene(scene, quality::kWidth, quality::kHeight, quality::kLensSamples, aperture.shape);
            r.result = quality::runGate(device, r.render);
            std::printf("%-16s %-16s input %.2f, ffx-dof %.2f, gain %+.2f, circular gather %.2f dB (%.1f s)\n",
                        scene.c_str(), aperture.name.c_str(), r.result.input.psnr, r.result.effect.psnr,
                        r.result.effect.psnr - r.result.input.psnr, r.result.gather.psnr, seconds(start));
            return runs.emplace(key, std::move(r)).first->second;
        };
        const std::vector<std::string> scenes = {"far-highlights", "mid-lights"};
        const quality::NamedAperture& circle = quality::pictureApertures().front();
        md << "### Scenes\n\n"
           << "The highlight scenes of docs/quality.md, " << quality::kWidth << "x" << quality::kHeight << ", "
           << quality::kLensSamples
           << " lens samples, the truth rendered through the shaped aperture and ffx-dof given the same shape; PSNR "
              "against that truth. The circle's rows are the round aperture's gates of docs/quality.md. The circular "
              "gather (docs/quality.md's baseline: round, no depth order) is shown against the shaped truth too.\n\n"
           << "| scene | aperture | PSNR input | PSNR ffx-dof | gain | the circle's gain | PSNR circular gather | "
              "margin | result |\n|---|---|---|---|---|---|---|---|---|\n";
        std::ostringstream rationale;
        for (const std::string& scene : scenes) {
            const SceneRun& round = run(scene, circle);
            const double circleGain = round.result.effect.psnr - round.result.input.psnr;
            for (const quality::SceneGate& gate : quality::sceneGates()) {
                if (gate.scene != scene) continue;
                md << "| " << scene << " | " << circle.title << " | " << number(round.result.input.psnr, "%.2f")
                   << " | " << number(round.result.effect.psnr, "%.2f") << " | " << number(circleGain, "%+.2f")
                   << " | - | " << number(round.result.gather.psnr, "%.2f") << " | "
                   << number(gate.psnrMarginDb, "%.1f") << " | " << verdict(round.result.psnrGate(gate.psnrMarginDb))
                   << " |\n";
            }
            for (const quality::ShapedSceneGate& gate : quality::shapedSceneGates()) {
                if (gate.scene != scene) continue;
                const SceneRun& shaped = run(scene, gate.aperture);
                const quality::GateResult& result = shaped.result;
                md << "| " << scene << " | " << gate.aperture.title << " | " << number(result.input.psnr, "%.2f")
                   << " | " << number(result.effect.psnr, "%.2f") << " | "
                   << number(result.effect.psnr - result.input.psnr, "%+.2f") << " | " << number(circleGain, "%+.2f")
                   << " | " << number(result.gather.psnr, "%.2f") << " | " << number(gate.psnrMarginDb, "%.1f") << " | "
                   << verdict(result.psnrGate(gate.psnrMarginDb)) << " |\n";
                rationale << "- " << scene << ", " << gate.aperture.title << ": " << gate.rationale << ".\n";
            }
        }
        md << "\nWhy these margins:\n\n" << rationale.str() << "\n";

        // ---- pictures of the scenes per aperture ----
        md << "### Pictures\n\n"
           << "Every picture aperture on both highlight scenes (the shapes without a gate above are measured here "
              "only). Pictures of "
           << kPictureScene
           << ", left to right: input (pinhole), ffx-dof, truth through "
              "the same aperture; 8-bit sRGB, values above 1 clipped.\n\n"
           << "| scene | aperture | PSNR input | PSNR ffx-dof | gain |\n|---|---|---|---|---|\n";
        std::ostringstream pictures;
        for (const std::string& scene : {std::string("mid-lights"), std::string("far-highlights")}) {
            for (const quality::NamedAperture& aperture : quality::pictureApertures()) {
                const SceneRun& shaped = run(scene, aperture);
                const quality::GateResult& result = shaped.result;
                md << "| " << scene << " | " << aperture.title << " | " << number(result.input.psnr, "%.2f") << " | "
                   << number(result.effect.psnr, "%.2f") << " | "
                   << number(result.effect.psnr - result.input.psnr, "%+.2f") << " |\n";
                if (scene != kPictureScene) continue;
                const std::string file = scene + "_" + aperture.name + ".png";
                writePng(file, sideBySide({shaped.render.pinhole.color, result.ours, shaped.render.truth}));
                pictures << "**" << scene << ", " << aperture.title << "**\n\n![" << scene << " " << aperture.name
                         << "](images/aperture/" << file << ")\n\n";
            }
        }
        md << "\n" << pictures.str();
        const std::string generated = md.str();
        if (docs.empty()) {
            std::printf("\n%s", generated.c_str());
        } else {
            replaceBetweenMarkers(std::filesystem::path(docs) / "aperture.md", generated);
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "error: %s\n", error.what());
        return 1;
    }
    return 0;
}
