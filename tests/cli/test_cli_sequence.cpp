// `ffx-dof apply --frames`: sequences run as the built program. A frame of a sequence equals the same
// frame run alone byte for byte, resumed runs skip complete outputs, several processes on overlapping
// ranges write every frame whole and once, SIGTERM / SIGINT leave no partial or temporary file.
#include "ffx_dof_imageio.h"
#include "ffx_dof_metrics.h"
#include "ffx_dof_reference.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <catch2/catch.hpp>

#include "ffx_dof_temp_folder.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace fs = std::filesystem;
using ffxdof::io::ImageR;
using ffxdof::io::ImageRGBA;

namespace {

// A fresh folder per test case, removed at the end.
class TempFolder : public ffxdof::testing::TempFolder {
public:
    TempFolder() : ffxdof::testing::TempFolder("ffx_dof_seq_test_") {}
};
using ffxdof::testing::readText;

// A running ffx-dof, its output in files of the folder.
struct Process {
    pid_t pid = -1;
    std::string outPath, errPath;
};

Process start(const TempFolder& folder, const std::vector<std::string>& arguments, const std::string& tag,
              bool withoutRenameat2 = false) {
    Process process;
    process.outPath = folder / (tag + ".out");
    process.errPath = folder / (tag + ".err");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, process.outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, process.errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> all = {FFX_DOF_CLI_PROGRAM};
    all.insert(all.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& argument : all) argv.push_back(argument.data());
    argv.push_back(nullptr);
    std::vector<std::string> environment;
    for (char** variable = environ; *variable != nullptr; ++variable) environment.emplace_back(*variable);
    if (withoutRenameat2) environment.emplace_back("FFX_DOF_TEST_NO_RENAMEAT2=1");
    std::vector<char*> envp;
    for (std::string& variable : environment) envp.push_back(variable.data());
    envp.push_back(nullptr);
    REQUIRE(posix_spawn(&process.pid, FFX_DOF_CLI_PROGRAM, &actions, nullptr, argv.data(), envp.data()) == 0);
    posix_spawn_file_actions_destroy(&actions);
    return process;
}

struct Finished {
    int exitCode = -1;
    std::string out, err;
};

Finished finish(const Process& process) {
    int status = 0;
    waitpid(process.pid, &status, 0);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readText(process.outPath), readText(process.errPath)};
}

Finished run(const TempFolder& folder, const std::vector<std::string>& arguments, const std::string& tag = "run") {
    return finish(start(folder, arguments, tag));
}

constexpr uint32_t kWidth = 64, kHeight = 48;

// Frame f: a checker shifted by f pixels (a pan), depth near on the left, far on the right.
void writeFrame(const TempFolder& folder, int frame, const std::string& colorName, const std::string& depthName) {
    ImageRGBA color(kWidth, kHeight);
    ImageR depth(kWidth, kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const bool bright = (((x + uint32_t(frame)) / 3) + (y / 3)) % 2 == 0;
            float* pixel = color.at(x, y);
            pixel[0] = bright ? 0.9f : 0.1f;
            pixel[1] = bright ? 0.7f : 0.2f;
            pixel[2] = bright ? 0.5f : 0.05f;
            pixel[3] = 1.0f;
            depth.at(x, y) = x < kWidth / 3 ? 0.6f : (x < 2 * kWidth / 3 ? 3.9f : 40.0f);
        }
    }
    ffxdof::io::writeExr(folder / colorName, color, ffxdof::io::ExrPixelType::Float);
    ffxdof::io::writeExr(folder / depthName, depth, ffxdof::io::ExrPixelType::Float, "Z");
}

std::string frameName(const char* prefix, int frame) {
    char name[64];
    std::snprintf(name, sizeof(name), "%s.%04d.exr", prefix, frame);
    return name;
}

void writeShot(const TempFolder& folder, int first, int last) {
    for (int frame = first; frame <= last; ++frame)
        writeFrame(folder, frame, frameName("c", frame), frameName("z", frame));
}

std::vector<std::string> applyArguments(const TempFolder& folder, const std::string& frames,
                                        std::vector<std::string> extra = {}) {
    std::vector<std::string> arguments = {"apply",
                                          "--color",
                                          folder / "c.####.exr",
                                          "--depth",
                                          folder / "z.%04d.exr",
                                          "--out",
                                          folder / "o.####.exr",
                                          "--frames",
                                          frames,
                                          "--focus",
                                          "4",
                                          "--fstop",
                                          "1.4",
                                          "--sensor-width",
                                          "4"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return arguments;
}

// Files whose name says they are temporary (the writers' ".NAME.tmpPID_N").
std::vector<std::string> temporaryFiles(const TempFolder& folder) {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        const std::string name = entry.path().filename().string();
        if (name.find(".tmp") != std::string::npos) found.push_back(name);
    }
    return found;
}

bool isCompleteExr(const std::string& path) {
    try {
        const ffxdof::io::ExrProbe probe = ffxdof::io::probeExr(path);
        return probe.complete && probe.width == kWidth && probe.height == kHeight;
    } catch (const ffxdof::io::IoError&) {
        return false;
    }
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("sequence usage errors", "[cli]") {
    TempFolder folder;
    const auto requireError = [&](const std::vector<std::string>& arguments, int code, const std::string& fragment) {
        const Finished result = run(folder, arguments);
        INFO(result.err);
        CHECK(result.exitCode == code);
        CHECK(result.err.rfind("ffx-dof: error: ", 0) == 0);
        CHECK(count(result.err, "\n") == 1);
        CHECK_THAT(result.err, Catch::Contains(fragment));
    };
    requireError(applyArguments(folder, "1-x"), 1, "--frames");
    requireError(applyArguments(folder, "9-3"), 3, "before the first");
    requireError(applyArguments(folder, "1-3", {"--chunk", "4/3"}), 3, "--chunk");
    requireError({"apply", "--color", "c.####.exr", "--depth", "z.exr", "--out", "o.exr", "--focus", "2"}, 1,
                 "--frames");
    requireError({"apply", "--color", "c.exr", "--depth", "z.exr", "--out", "o.exr", "--focus", "2", "--chunk", "1/2"},
                 1, "--chunk needs --frames");
    requireError(
        {"apply", "--color", "c.####.exr", "--depth", "z.exr", "--out", "o.exr", "--focus", "2", "--frames", "1-3"}, 1,
        "frame-number field in --out");
    requireError({"apply", "--color", "c.####.exr", "--depth", "z.exr", "--out", "o.####.png", "--focus", "2",
                  "--frames", "1-3"},
                 1, "must be .exr");
    requireError({"apply", "--color", "c.####.exr", "--depth", "z.exr", "--out", "o.####.exr", "--frames", "1-3"}, 1,
                 "--focus");
}

TEST_CASE("a sequence's frames equal the frames run alone, a resumed run skips them, --overwrite redoes them",
          "[vulkan]") {
    TempFolder folder;
    writeShot(folder, 1, 3);
    // With the validation layer: the session's reused images and per-frame contexts raise no message.
    const Finished first = run(folder, applyArguments(folder, "1-3", {"--validate"}));
    INFO(first.out << first.err);
    REQUIRE(first.exitCode == 0);
    CHECK_THAT(first.out, Catch::Contains("written 3, skipped 0"));
    CHECK(count(first.out, ": wrote ") == 3);  // plain lines, not a terminal

    // Frame 2 alone, and the sequence with every stage one after the other: the same bytes.
    const Finished alone =
        run(folder, {"apply", "--color", folder / "c.0002.exr", "--depth", folder / "z.0002.exr", "--out",
                     folder / "alone.exr", "--focus", "4", "--fstop", "1.4", "--sensor-width", "4"});
    REQUIRE(alone.exitCode == 0);
    CHECK((readText(folder / "alone.exr") == readText(folder / "o.0002.exr")));
    CHECK((readText(folder / "o.0001.exr") != readText(folder / "o.0002.exr")));
    fs::create_directories(folder / "serial");
    std::vector<std::string> serial = applyArguments(folder, "1-3", {"--no-overlap"});
    serial[6] = folder / "serial/o.####.exr";
    REQUIRE(run(folder, serial).exitCode == 0);
    for (int frame = 1; frame <= 3; ++frame) {
        CHECK((readText(folder / ("serial/" + frameName("o", frame))) == readText(folder / frameName("o", frame))));
    }

    // Resumed: nothing to do. A truncated output is redone; --overwrite redoes everything.
    struct stat before {};
    REQUIRE(::stat((folder / "o.0001.exr").c_str(), &before) == 0);
    const Finished resumed = run(folder, applyArguments(folder, "1-3"));
    REQUIRE(resumed.exitCode == 0);
    CHECK_THAT(resumed.out, Catch::Contains("written 0, skipped 3"));
    struct stat after {};
    REQUIRE(::stat((folder / "o.0001.exr").c_str(), &after) == 0);
    CHECK(before.st_ino == after.st_ino);
    const std::string good = readText(folder / "o.0003.exr");
    fs::resize_file(folder / "o.0003.exr", good.size() / 2);
    const Finished repaired = run(folder, applyArguments(folder, "1-3"));
    INFO(repaired.out);
    REQUIRE(repaired.exitCode == 0);
    CHECK_THAT(repaired.out, Catch::Contains("redoing") && Catch::Contains("written 1, skipped 2"));
    CHECK((readText(folder / "o.0003.exr") == good));
    const Finished overwritten = run(folder, applyArguments(folder, "1-3", {"--overwrite"}));
    REQUIRE(overwritten.exitCode == 0);
    CHECK_THAT(overwritten.out, Catch::Contains("written 3, skipped 0"));
    CHECK(temporaryFiles(folder).empty());
}

TEST_CASE("several processes on overlapping ranges write every frame whole, once, with no temporary file", "[vulkan]") {
    TempFolder folder;
    constexpr int kFrames = 8;
    writeShot(folder, 1, kFrames);
    std::vector<Process> processes;
    // Two of them land frames with link() instead of renameat2 (as on NFS).
    processes.push_back(start(folder, applyArguments(folder, "1-8"), "p0"));
    processes.push_back(start(folder, applyArguments(folder, "3-8"), "p1", true));
    processes.push_back(start(folder, applyArguments(folder, "1-6"), "p2"));
    processes.push_back(start(folder, applyArguments(folder, "1-8", {"--chunk", "2/2"}), "p3", true));
    size_t wrote = 0;
    for (const Process& process : processes) {
        const Finished result = finish(process);
        INFO(result.out << result.err);
        CHECK(result.exitCode == 0);
        wrote += count(result.out, ": wrote ");
    }
    CHECK(wrote == kFrames);  // every frame landed exactly once; the others were skipped
    for (int frame = 1; frame <= kFrames; ++frame) CHECK(isCompleteExr(folder / frameName("o", frame)));
    CHECK(temporaryFiles(folder).empty());
    // And each equals a run of that frame alone (the frames do not depend on who wrote them).
    const Finished alone =
        run(folder, {"apply", "--color", folder / "c.0005.exr", "--depth", folder / "z.0005.exr", "--out",
                     folder / "alone.exr", "--focus", "4", "--fstop", "1.4", "--sensor-width", "4"});
    REQUIRE(alone.exitCode == 0);
    CHECK((readText(folder / "alone.exr") == readText(folder / "o.0005.exr")));
}

TEST_CASE("SIGTERM and SIGINT end a sequence with their codes and leave no partial or temporary file", "[vulkan]") {
    TempFolder folder;
    writeFrame(folder, 1, "c.exr", "z.exr");
    for (const auto& [signal, code, name] : {std::tuple{SIGTERM, 143, "SIGTERM"}, std::tuple{SIGINT, 130, "SIGINT"}}) {
        // One input for every frame (a constant name), a long range: the signal comes mid-way.
        const Process process = start(folder,
                                      {"apply", "--color", folder / "c.exr", "--depth", folder / "z.exr", "--out",
                                       folder / (std::string(name) + ".####.exr"), "--frames", "1-2000", "--focus", "4",
                                       "--fstop", "1.4", "--sensor-width", "4"},
                                      name);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        while (!fs::exists(folder / (std::string(name) + ".0003.exr")) && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        ::kill(process.pid, signal);
        const Finished result = finish(process);
        INFO(result.out << result.err);
        CHECK(result.exitCode == code);
        CHECK_THAT(result.err, Catch::StartsWith("ffx-dof: error: interrupted by " + std::string(name)));
        CHECK(count(result.err, "\n") == 1);
        CHECK(temporaryFiles(folder).empty());
        size_t outputs = 0;
        for (const auto& entry : fs::directory_iterator(folder.path())) {
            const std::string file = entry.path().filename().string();
            if (file.rfind(name, 0) == 0 && entry.path().extension() == ".exr") {
                ++outputs;
                CHECK(isCompleteExr(entry.path().string()));
            }
        }
        CHECK(outputs >= 3);
        CHECK(outputs < 2000);
    }
}

TEST_CASE("camera track, --keep-layers and the CoC clamp report", "[vulkan]") {
    TempFolder folder;
    writeShot(folder, 1, 2);
    // A track: frame 1 as the command line (focus 4), frame 2 focused near.
    std::ofstream(folder / "track.csv") << "frame,focus,fstop\n1,4,1.4\n2,0.8,1.4\n";
    std::vector<std::string> tracked = applyArguments(folder, "1-2", {"--camera-track", folder / "track.csv"});
    tracked[6] = folder / "t.####.exr";
    const Finished withTrack = run(folder, tracked);
    INFO(withTrack.out << withTrack.err);
    REQUIRE(withTrack.exitCode == 0);
    REQUIRE(run(folder, applyArguments(folder, "1-2")).exitCode == 0);
    CHECK((readText(folder / "t.0001.exr") == readText(folder / "o.0001.exr")));
    CHECK((readText(folder / "t.0002.exr") != readText(folder / "o.0002.exr")));

    // --keep-layers: the colour file's other channels and its attributes reach the output.
    {
        const ImageRGBA color = ffxdof::io::readExrColor(folder / "c.0001.exr");
        Imf::Header header{int(kWidth), int(kHeight)};
        header.insert("owner", Imf::StringAttribute("shot 42"));
        for (const char* channel : {"R", "G", "B", "A", "Z"})
            header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
        std::vector<float> z(size_t(kWidth) * kHeight, 7.0f);
        Imf::FrameBuffer frameBuffer;
        const char* names[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c) {
            frameBuffer.insert(names[c],
                               Imf::Slice(Imf::FLOAT, (char*)(color.pixels.data() + c), 16, 16 * size_t(kWidth)));
        }
        frameBuffer.insert("Z", Imf::Slice(Imf::FLOAT, (char*)z.data(), 4, 4 * size_t(kWidth)));
        Imf::OutputFile file((folder / "layered.exr").c_str(), header);
        file.setFrameBuffer(frameBuffer);
        file.writePixels(int(kHeight));
    }
    const Finished kept = run(folder, {"apply", "--color", folder / "layered.exr", "--depth", folder / "z.0001.exr",
                                       "--out", folder / "kept.exr", "--focus", "4", "--fstop", "1.4", "--sensor-width",
                                       "4", "--keep-layers", "--out-type", "float"});
    INFO(kept.err);
    REQUIRE(kept.exitCode == 0);
    Imf::InputFile keptFile((folder / "kept.exr").c_str());
    CHECK(keptFile.header().channels().findChannel("Z") != nullptr);
    const auto* owner = keptFile.header().findTypedAttribute<Imf::StringAttribute>("owner");
    REQUIRE(owner != nullptr);
    CHECK(owner->value() == "shot 42");
    CHECK(ffxdof::io::readExrChannel(folder / "kept.exr", "Z").pixels[100] == 7.0f);

    // Without --coc-limit nothing is clamped; with one that bites, the run says how many pixels.
    const Finished clamped = run(folder, {"apply", "--color", folder / "c.0001.exr", "--depth", folder / "z.0001.exr",
                                          "--out", folder / "clamped.exr", "--focus", "4", "--fstop", "1.4",
                                          "--sensor-width", "4", "--coc-limit", "0.1"});
    REQUIRE(clamped.exitCode == 0);
    CHECK_THAT(clamped.out, Catch::Contains("--coc-limit 0.1 clamps 1008 pixels"));
    CHECK_THAT(withTrack.out, !Catch::Contains("clamps"));
}

TEST_CASE("a slow pan rendered by the reference renderer flickers at most 1.2 times the truth", "[vulkan]") {
    // 8 frames of busy-background at 96x64, the camera moving sideways by 1 cm a frame (about a third of a
    // pixel on the in-focus object); the truth with 32 lens samples, the same sample pattern every frame.
    TempFolder folder;
    ffxdof::ref::SceneSetup setup = ffxdof::ref::makeScene("busy-background", 96, 64);
    ffxdof::ref::RenderSettings settings;
    settings.lensSamples = 32;
    ffxdof::metrics::TemporalChange truthChange, outputChange;
    const ffxdof::ref::Camera start = setup.camera;
    for (int frame = 1; frame <= 8; ++frame) {
        ffxdof::ref::Camera camera = start;
        camera.position.x += 0.01 * frame;
        camera.target.x += 0.01 * frame;
        const ffxdof::ref::PinholeImages pinhole = ffxdof::ref::renderPinhole(setup.scene, camera, settings);
        ffxdof::io::writeExr(folder / frameName("c", frame), pinhole.color, ffxdof::io::ExrPixelType::Float);
        ffxdof::io::writeExr(folder / frameName("z", frame), pinhole.depth, ffxdof::io::ExrPixelType::Float, "Z");
        ffxdof::io::writeExr(folder / frameName("truth", frame),
                             ffxdof::ref::renderThinLens(setup.scene, camera, settings).color,
                             ffxdof::io::ExrPixelType::Float);
    }
    const auto number = [](double value) { return std::to_string(value); };
    const Finished applied = run(
        folder, {"apply", "--color", folder / "c.####.exr", "--depth", folder / "z.####.exr", "--out",
                 folder / "o.####.exr", "--frames", "1-8", "--out-type", "float", "--focus",
                 number(start.focusDistance), "--focal-length", number(start.focalLength * 1000.0), "--sensor-width",
                 number(start.sensorWidth * 1000.0), "--aperture-radius", number(start.apertureRadius)});
    INFO(applied.out << applied.err);
    REQUIRE(applied.exitCode == 0);
    for (int frame = 1; frame <= 8; ++frame) {
        truthChange.add(ffxdof::io::readExrColor(folder / frameName("truth", frame)));
        outputChange.add(ffxdof::io::readExrColor(folder / frameName("o", frame)));
    }
    const double ratio = outputChange.mean() / truthChange.mean();
    CAPTURE(truthChange.mean(), outputChange.mean(), ratio);
    CHECK(truthChange.mean() > 0.0);
    CHECK(ratio <= 1.2);
    // The same figures from `ffx-dof compare --frames`.
    const Finished compared = run(
        folder, {"compare", "--ref", folder / "truth.####.exr", "--test", folder / "o.####.exr", "--frames", "1-8"});
    INFO(compared.out << compared.err);
    REQUIRE(compared.exitCode == 0);
    char expected[64];
    std::snprintf(expected, sizeof(expected), "flicker ratio %.3f", ratio);
    CHECK_THAT(compared.out, Catch::Contains(expected));
    WARN("pan flicker: truth " << truthChange.mean() << ", ffx-dof " << outputChange.mean() << ", ratio " << ratio);
}

namespace {

std::string shellQuote(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

// The first ```sh block after `heading` in a Markdown file.
std::string markdownBlock(const std::string& path, const std::string& heading) {
    const std::string text = readText(path);
    const size_t at = text.find(heading);
    if (at == std::string::npos) return "";
    const size_t begin = text.find("```sh\n", at);
    const size_t end = text.find("\n```", begin + 6);
    if (begin == std::string::npos || end == std::string::npos) return "";
    return text.substr(begin + 6, end - begin - 6 + 1);
}

bool replaceOnce(std::string& text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    if (at == std::string::npos) return false;
    text.replace(at, from.size(), to);
    return true;
}

// munged, slurmctld and slurmd for this node only, in a folder of their own, on ports of their own;
// stopped (by the process ids they wrote) at the end.
class LocalSlurm {
public:
    explicit LocalSlurm(const TempFolder& folder) : root_(folder / "slurm") {
        fs::create_directories(root_ + "/state");
        fs::create_directories(root_ + "/spool");
        fs::create_directories(root_ + "/munge");
        fs::permissions(root_ + "/munge", fs::perms::owner_all, fs::perm_options::replace);
        const int port = 20000 + int(getpid() % 5000) * 2;
        char host[256] = {};
        gethostname(host, sizeof(host) - 1);
        std::string shortHost(host);
        shortHost = shortHost.substr(0, shortHost.find('.'));
        std::ofstream(root_ + "/slurm.conf")
            << "ClusterName=ffxdoftest\nSlurmctldHost=" << shortHost << "\nSlurmUser=root\nSlurmdUser=root\n"
            << "AuthType=auth/munge\nAuthInfo=socket=" << root_ << "/munge/munge.sock\nCredType=cred/munge\n"
            << "StateSaveLocation=" << root_ << "/state\nSlurmdSpoolDir=" << root_ << "/spool\n"
            << "SlurmctldPidFile=" << root_ << "/slurmctld.pid\nSlurmdPidFile=" << root_ << "/slurmd.pid\n"
            << "SlurmctldLogFile=" << root_ << "/slurmctld.log\nSlurmdLogFile=" << root_ << "/slurmd.log\n"
            << "SlurmctldPort=" << port << "\nSlurmdPort=" << port + 1 << "\n"
            << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\nSchedulerType=sched/builtin\n"
            << "SelectType=select/cons_tres\nSelectTypeParameters=CR_Core\nReturnToService=2\nMpiDefault=none\n"
            << "JobAcctGatherType=jobacct_gather/none\nAccountingStorageType=accounting_storage/none\n"
            << "NodeName=" << shortHost << " CPUs=2 RealMemory=8192 State=UNKNOWN\n"
            << "PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n";
        const std::string munge = root_ + "/munge/";
        started_ =
            std::system(("dd if=/dev/urandom of=" + munge + "munge.key bs=1024 count=1 2>/dev/null && chmod 600 " +
                         munge + "munge.key && munged --force --socket=" + munge + "munge.sock --key-file=" + munge +
                         "munge.key --pid-file=" + munge + "munged.pid --log-file=" + munge +
                         "munged.log --seed-file=" + munge + "munge.seed && slurmctld -i -f " + conf() +
                         " && slurmd -f " + conf())
                            .c_str()) == 0;
        // Ready once the node is idle.
        for (int i = 0; started_ && i < 100 && !ready_; ++i) {
            ready_ = std::system(("SLURM_CONF=" + conf() + " sinfo -h -o %t 2>/dev/null | grep -q idle").c_str()) == 0;
            if (!ready_) std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
    }
    ~LocalSlurm() {
        for (const char* pidFile : {"/slurmd.pid", "/slurmctld.pid", "/munge/munged.pid"}) {
            const std::string text = readText(root_ + pidFile);
            const pid_t pid = pid_t(std::atoi(text.c_str()));
            if (pid <= 1) continue;
            ::kill(pid, SIGTERM);
            for (int i = 0; i < 50 && ::kill(pid, 0) == 0; ++i)
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    }
    bool ready() const { return ready_; }
    std::string conf() const { return root_ + "/slurm.conf"; }
    std::string logs() const { return readText(root_ + "/slurmctld.log") + readText(root_ + "/slurmd.log"); }

private:
    std::string root_;
    bool started_ = false, ready_ = false;
};

}  // namespace

TEST_CASE("the SLURM job-array script of docs/cli.md on a one-node SLURM on this machine", "[vulkan][slurm]") {
    // Needs slurm-wlm and munge (tools/setup.sh installs them) and root (the daemons run as root here).
    if (std::system("command -v munged slurmctld slurmd sbatch sinfo >/dev/null 2>&1") != 0 || ::geteuid() != 0) {
        WARN("SKIPPED: the SLURM test needs slurm-wlm and munge installed (tools/setup.sh) and root");
        return;
    }
    TempFolder folder;
    const LocalSlurm slurm(folder);
    if (!slurm.ready()) {
        WARN("SKIPPED: a one-node SLURM could not be started here:\n" << slurm.logs());
        return;
    }
    std::string script = markdownBlock(FFX_DOF_SOURCE_DIR "/docs/cli.md", "#### On a farm (SLURM)");
    INFO(script);
    REQUIRE(script.find("#!/bin/bash") == 0);
    // The docs' shot is 100 frames in 20 shares of 2 CPUs; here 12 frames in 4 shares of 1 CPU (two run at
    // once on this 2-CPU node), in this test's folder.
    const std::string shot = (folder.path() / "s42").string();
    while (replaceOnce(script, "/shows/s42", shot)) {
    }
    REQUIRE(replaceOnce(script, "--frames 1001-1100", "--frames 1001-1012"));
    REQUIRE(replaceOnce(script, "--array=1-20%8", "--array=1-4"));
    REQUIRE(replaceOnce(script, "--cpus-per-task=2", "--cpus-per-task=1"));
    std::ofstream(folder / "dof-shot.sh") << script;
    fs::create_directories(shot);
    std::ofstream camera(shot + "/camera.csv");
    camera << "frame,focus,fstop\n";
    for (int frame = 1001; frame <= 1012; ++frame) {
        writeFrame(folder, frame, "s42/" + frameName("beauty", frame), "s42/" + frameName("z", frame));
        camera << frame << "," << 4.0 + 0.01 * (frame - 1001) << ",1.4\n";
    }
    camera.close();

    const std::string binDirectory = fs::path(FFX_DOF_CLI_PROGRAM).parent_path().string();
    // sbatch --wait polls with a growing interval; this test asks squeue every 100 ms instead.
    const std::string environment = "SLURM_CONF=" + shellQuote(slurm.conf()) + " ";
    const int status =
        std::system((environment + "PATH=" + shellQuote(binDirectory) +
                     ":\"$PATH\" sbatch --parsable --chdir=" + shellQuote(folder.path().string()) + " " +
                     shellQuote(folder / "dof-shot.sh") + " > " + shellQuote(folder / "sbatch.out") + " 2>&1")
                        .c_str());
    const std::string jobId = readText(folder / "sbatch.out").substr(0, readText(folder / "sbatch.out").find('\n'));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline &&
           std::system((environment + "squeue -h -j " + shellQuote(jobId) + " 2>/dev/null | grep -q .").c_str()) == 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    std::string logs;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        if (entry.path().extension() == ".log") logs += readText(entry.path());
    }
    INFO("sbatch: " << readText(folder / "sbatch.out") << "\ntask logs:\n" << logs);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    CHECK(count(logs, "done: ") == 4);
    CHECK(count(logs, ": wrote ") == 12);
    for (int frame = 1001; frame <= 1012; ++frame) CHECK(isCompleteExr(shot + "/dof/" + frameName("dof", frame)));
    CHECK(temporaryFiles(folder).empty());
}

TEST_CASE("frame-to-frame change: the mean |luminance difference| of clamped frames", "[cli]") {
    ImageRGBA black(4, 2), white(4, 2), bright(4, 2);
    for (size_t i = 0; i < white.pixels.size(); ++i) {
        white.pixels[i] = 1.0f;
        bright.pixels[i] = 50.0f;
    }
    CHECK(ffxdof::metrics::frameChange(black, black) == 0.0);
    CHECK(ffxdof::metrics::frameChange(black, white) == Approx(1.0));
    CHECK(ffxdof::metrics::frameChange(white, bright) == 0.0);  // what a display shows does not change
    ffxdof::metrics::TemporalChange change;
    for (const ImageRGBA* frame : {&black, &white, &white, &black}) change.add(*frame);
    CHECK(change.pairs() == 3);
    CHECK(change.mean() == Approx(2.0 / 3.0));
    CHECK_THROWS_AS(change.add(ImageRGBA(2, 2)), std::invalid_argument);
}
