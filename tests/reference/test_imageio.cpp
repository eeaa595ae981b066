#include "ffx_dof_imageio.h"
#include "ffx_dof_temp_folder.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <stb_image.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <ostream>

using namespace ffxdof::io;

namespace {

ImageRGBA makeGradient(uint32_t width, uint32_t height) {
    ImageRGBA image(width, height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            // Multiples of 1/64 below 4 are exact in half precision.
            p[0] = float(x) / 64.0f, p[1] = float(y) / 64.0f, p[2] = float((x * 7 + y * 3) % 256) / 64.0f;
            p[3] = float((x + y) % 2);
        }
    }
    return image;
}

std::string readBytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), {}};
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary);
    file << bytes;
}

std::string errorOf(const std::function<void()>& operation) {
    try {
        operation();
    } catch (const IoError& error) {
        return error.what();
    }
    return "(no IoError thrown)";
}

// A two-part file written with OpenEXR itself: part "beauty" holds R, G, B and beauty.R/G/B; part
// "aux" holds depth.Z and Depth.V.
void writeMultiPart(const std::string& path, uint32_t width, uint32_t height) {
    Imf::Header beauty{int(width), int(height)};
    beauty.setName("beauty");
    beauty.setType(Imf::SCANLINEIMAGE);
    Imf::Header aux = beauty;
    aux.setName("aux");
    for (const char* name : {"R", "G", "B", "beauty.R", "beauty.G", "beauty.B"}) {
        beauty.channels().insert(name, Imf::Channel(Imf::FLOAT));
    }
    for (const char* name : {"depth.Z", "Depth.V"}) aux.channels().insert(name, Imf::Channel(Imf::FLOAT));
    Imf::MultiPartOutputFile file(path.c_str(), std::vector<Imf::Header>{beauty, aux}.data(), 2);
    std::vector<float> values(size_t(width) * height);
    std::vector<std::vector<float>> planes;
    const auto fill = [&](float base) {
        for (size_t i = 0; i < values.size(); ++i) values[i] = base + float(i);
        planes.push_back(values);
        return planes.back().data();
    };
    planes.reserve(8);
    Imf::FrameBuffer beautyBuffer, auxBuffer;
    const size_t row = sizeof(float) * width;
    beautyBuffer.insert("R", Imf::Slice(Imf::FLOAT, (char*)fill(1000), sizeof(float), row));
    beautyBuffer.insert("G", Imf::Slice(Imf::FLOAT, (char*)fill(2000), sizeof(float), row));
    beautyBuffer.insert("B", Imf::Slice(Imf::FLOAT, (char*)fill(3000), sizeof(float), row));
    beautyBuffer.insert("beauty.R", Imf::Slice(Imf::FLOAT, (char*)fill(4000), sizeof(float), row));
    beautyBuffer.insert("beauty.G", Imf::Slice(Imf::FLOAT, (char*)fill(5000), sizeof(float), row));
    beautyBuffer.insert("beauty.B", Imf::Slice(Imf::FLOAT, (char*)fill(6000), sizeof(float), row));
    auxBuffer.insert("depth.Z", Imf::Slice(Imf::FLOAT, (char*)fill(7000), sizeof(float), row));
    auxBuffer.insert("Depth.V", Imf::Slice(Imf::FLOAT, (char*)fill(8000), sizeof(float), row));
    Imf::OutputPart beautyPart(file, 0), auxPart(file, 1);
    beautyPart.setFrameBuffer(beautyBuffer);
    beautyPart.writePixels(int(height));
    auxPart.setFrameBuffer(auxBuffer);
    auxPart.writePixels(int(height));
}

}  // namespace

TEST_CASE("EXR colour round-trips in float exactly and in half within half precision", "[imageio]") {
    const ffxdof::testing::TempFolder dir("ffx_dof_reference_test_");
    const ImageRGBA image = makeGradient(37, 11);
    writeExr(dir / "float.exr", image, ExrPixelType::Float);
    const ImageRGBA floats = readExrColor(dir / "float.exr");
    CHECK(floats.width == 37);
    CHECK(floats.height == 11);
    CHECK(floats.pixels == image.pixels);

    ImageRGBA inexact = image;
    inexact.pixels[5] = 0.1f;  // not representable in half: within half's 2^-11 relative precision
    writeExr(dir / "half.exr", inexact, ExrPixelType::Half);
    const ImageRGBA halves = readExrColor(dir / "half.exr");
    REQUIRE(halves.pixels.size() == inexact.pixels.size());
    for (size_t i = 0; i < inexact.pixels.size(); ++i) {
        CHECK(halves.pixels[i] == Approx(inexact.pixels[i]).epsilon(1.0 / 2048).margin(1e-7));
    }
    CHECK(halves.pixels[5] != 0.1f);
}

TEST_CASE("a missing alpha channel reads as 1 and single channels round-trip", "[imageio]") {
    const ffxdof::testing::TempFolder dir("ffx_dof_reference_test_");
    ImageR depth(5, 3);
    for (size_t i = 0; i < depth.pixels.size(); ++i) depth.pixels[i] = 0.5f + float(i);
    writeExr(dir / "depth.exr", depth, ExrPixelType::Float, "Z");
    CHECK(readExrChannel(dir / "depth.exr").pixels == depth.pixels);
    CHECK(readExrChannel(dir / "depth.exr", "Z").pixels == depth.pixels);
    CHECK(listExrChannels(dir / "depth.exr") == std::vector<std::string>{"Z"});

    writeMultiPart(dir / "layers.exr", 4, 2);
    const ImageRGBA color = readExrColor(dir / "layers.exr");
    CHECK(color.at(1, 0)[0] == 1001.0f);
    CHECK(color.at(1, 0)[2] == 3001.0f);
    CHECK(color.at(3, 1)[3] == 1.0f);
}

TEST_CASE("multilayer and multi-part files: colour by layer prefix, channels by name", "[imageio]") {
    const ffxdof::testing::TempFolder dir("ffx_dof_reference_test_");
    writeMultiPart(dir / "layers.exr", 6, 3);
    const ImageRGBA beauty = readExrColor(dir / "layers.exr", "beauty");
    CHECK(beauty.at(2, 1)[0] == 4008.0f);
    CHECK(beauty.at(2, 1)[1] == 5008.0f);
    const ImageR z = readExrChannel(dir / "layers.exr", "depth.Z");
    CHECK(z.width == 6);
    CHECK(z.at(5, 2) == 7017.0f);
    CHECK(readExrChannel(dir / "layers.exr", "Depth.V").at(0, 0) == 8000.0f);
    CHECK(readExrChannel(dir / "layers.exr", "G").at(1, 0) == 2001.0f);
}

TEST_CASE("PNG output is 8-bit sRGB, alpha optional", "[imageio]") {
    const ffxdof::testing::TempFolder dir("ffx_dof_reference_test_");
    ImageRGBA image(3, 2);
    const float values[] = {0.0f, 0.5f, 1.0f, 2.0f, 0.0031308f, -1.0f};
    for (int i = 0; i < 6; ++i) {
        float* p = image.at(uint32_t(i % 3), uint32_t(i / 3));
        p[0] = p[1] = p[2] = values[i];
        p[3] = 0.5f;
    }
    writePng(dir / "rgb.png", image);
    writeImage(dir / "by_extension.PNG", image);
    writePng(dir / "rgba.png", image, true);
    int w = 0, h = 0, channels = 0;
    unsigned char* rgb = stbi_load((dir / "rgb.png").c_str(), &w, &h, &channels, 0);
    REQUIRE(rgb);
    CHECK(w == 3);
    CHECK(h == 2);
    CHECK(channels == 3);
    const int expected[] = {0, 188, 255, 255, 10, 0};  // sRGB(0.5) = 0.7354 -> 188; 0.0031308 -> 0.04045
    for (int i = 0; i < 6; ++i) CHECK(int(rgb[i * 3]) == expected[i]);
    stbi_image_free(rgb);
    unsigned char* rgba = stbi_load((dir / "rgba.png").c_str(), &w, &h, &channels, 0);
    REQUIRE(rgba);
    CHECK(channels == 4);
    CHECK(int(rgba[3]) == 128);
    stbi_image_free(rgba);
    CHECK(readBytes(dir / "by_extension.PNG") == readBytes(dir / "rgb.png"));
}

TEST_CASE("read errors are specific IoErrors, never crashes", "[imageio][errors]") {
    const ffxdof::testing::TempFolder dir("ffx_dof_reference_test_");
    CHECK_THAT(errorOf([&] { readExrColor(dir / "missing.exr"); }), Catch::Contains("file not found"));
    CHECK_THAT(errorOf([&] { readExrColor(dir.path().string()); }), Catch::Contains("directory"));

    writeBytes(dir / "text.exr", "this is not an image");
    CHECK_THAT(errorOf([&] { readExrColor(dir / "text.exr"); }), Catch::Contains("not an OpenEXR file"));

    // A valid file cut short, and one with its header bytes scrambled after the magic number.
    const ImageRGBA image = makeGradient(64, 64);
    writeExr(dir / "good.exr", image, ExrPixelType::Float);
    const std::string good = readBytes(dir / "good.exr");
    writeBytes(dir / "truncated.exr", good.substr(0, good.size() / 2));
    CHECK_THAT(errorOf([&] { readExrColor(dir / "truncated.exr"); }), Catch::Contains("corrupt"));
    for (size_t offset : {8u, 20u, 40u, 80u}) {
        std::string scrambled = good;
        for (size_t i = offset; i < offset + 24 && i < scrambled.size(); ++i) scrambled[i] = char(scrambled[i] ^ 0x5a);
        writeBytes(dir / "scrambled.exr", scrambled);
        CHECK_THROWS_AS(readExrColor(dir / "scrambled.exr"), IoError);
    }
    std::string corruptPixels = good;
    for (size_t i = good.size() - 200; i < good.size(); ++i) corruptPixels[i] = char(i * 37);
    writeBytes(dir / "corrupt_pixels.exr", corruptPixels);
    CHECK_THROWS_AS(readExrColor(dir / "corrupt_pixels.exr"), IoError);
}

TEST_CASE("channel errors list the channels that exist", "[imageio][errors]") {
    const ffxdof::testing::TempFolder dir("ffx_dof_reference_test_");
    writeExr(dir / "rgba.exr", makeGradient(4, 4), ExrPixelType::Half);
    CHECK_THAT(errorOf([&] { readExrChannel(dir / "rgba.exr"); }),
               Catch::Contains("4 channels") && Catch::Contains("A, B, G, R"));
    CHECK_THAT(errorOf([&] { readExrChannel(dir / "rgba.exr", "Z"); }),
               Catch::Contains("no channel named Z") && Catch::Contains("A, B, G, R"));
    ImageR depth(4, 4);
    writeExr(dir / "depth.exr", depth, ExrPixelType::Float, "Z");
    CHECK_THAT(errorOf([&] { readExrColor(dir / "depth.exr"); }),
               Catch::Contains("no colour channel R") && Catch::Contains("Z"));
    CHECK_THAT(errorOf([&] { readExrColor(dir / "rgba.exr", "beauty"); }), Catch::Contains("beauty.R"));
}

TEST_CASE("write errors leave existing files untouched and no temporary files behind", "[imageio][errors]") {
    const ffxdof::testing::TempFolder dir("ffx_dof_reference_test_");
    const ImageRGBA image = makeGradient(8, 8);
    CHECK_THAT(errorOf([&] { writeExr(dir / "no/such/dir/out.exr", image); }), Catch::Contains("does not exist"));
    writeBytes(dir / "plain_file", "x");
    CHECK_THROWS_AS(writeExr(dir / "plain_file/out.exr", image), IoError);
    CHECK_THAT(errorOf([&] { writeImage(dir / "out.tiff", image); }), Catch::Contains("unknown output format"));
    CHECK_THAT(errorOf([&] { writeExr(dir.path().string(), image); }), Catch::Contains("directory"));

    writeExr(dir / "keep.exr", image, ExrPixelType::Float);
    const std::string before = readBytes(dir / "keep.exr");
    ImageRGBA broken = image;
    broken.pixels.resize(10);  // inconsistent with its size
    CHECK_THAT(errorOf([&] { writeExr(dir / "keep.exr", broken); }), Catch::Contains("expected 256"));
    CHECK_THROWS_AS(writePng(dir / "keep.exr", ImageRGBA{}), IoError);
    // A writer that fails half-way: the destination keeps its old bytes and the temporary file goes.
    CHECK_THROWS_AS(writeFileReplacing(dir / "keep.exr",
                                       [](std::ostream& stream) {
                                           stream << "partial";
                                           throw IoError("simulated failure");
                                       }),
                    IoError);
    CHECK(readBytes(dir / "keep.exr") == before);
    size_t entries = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        (void)entry;
        ++entries;
    }
    CHECK(entries == 2);  // keep.exr and plain_file

    // A successful write replaces the file.
    writeExr(dir / "keep.exr", makeGradient(2, 2), ExrPixelType::Float);
    CHECK(readExrColor(dir / "keep.exr").width == 2);
}
