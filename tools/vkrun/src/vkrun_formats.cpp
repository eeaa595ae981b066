// Conversion of host float pixels to and from the texel layouts of the formats the harness makes.
// glm provides the half, packed-float and sRGB conversions.
#include "vkrun_internal.h"

#include <glm/gtc/color_space.hpp>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ffxdof::vkrun {

// The harness converts exactly the formats the backend accepts.
bool isSupportedColorFormat(VkFormat format) { return vk::isColorFormat(format); }

bool isSupportedDepthFormat(VkFormat format) { return vk::isDepthFormat(format); }

std::string formatName(VkFormat format) { return vk::formatName(format); }

uint32_t bytesPerTexel(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R16G16B16A16_SFLOAT:
            return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return 16;
        case VK_FORMAT_D16_UNORM:
            return 2;
        default:  // B10G11R11, RGBA8, D32, R32, and D24 (copied as X8_D24 in 32 bits)
            return 4;
    }
}

namespace {

uint8_t toUnorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

std::vector<uint8_t> encodeTexels(const HostImage& image, VkFormat format) {
    const size_t count = size_t(image.width) * image.height;
    std::vector<uint8_t> bytes(count * bytesPerTexel(format));
    for (size_t i = 0; i < count; ++i) {
        const float* p = &image.pixels[i * image.channels];
        uint8_t* out = &bytes[i * bytesPerTexel(format)];
        switch (format) {
            case VK_FORMAT_R16G16B16A16_SFLOAT:
                for (int c = 0; c < 4; ++c) {
                    const uint16_t half = glm::packHalf1x16(p[c]);
                    std::memcpy(out + 2 * c, &half, 2);
                }
                break;
            case VK_FORMAT_R32G32B32A32_SFLOAT:
                std::memcpy(out, p, 16);
                break;
            case VK_FORMAT_B10G11R11_UFLOAT_PACK32: {
                // Unsigned floats: negative values clamp to zero.
                const uint32_t packed = glm::packF2x11_1x10(glm::max(glm::vec3(p[0], p[1], p[2]), glm::vec3(0.0f)));
                std::memcpy(out, &packed, 4);
                break;
            }
            case VK_FORMAT_R8G8B8A8_UNORM:
                for (int c = 0; c < 4; ++c) out[c] = toUnorm8(p[c]);
                break;
            case VK_FORMAT_R8G8B8A8_SRGB: {
                const glm::vec3 encoded =
                    glm::convertLinearToSRGB(glm::clamp(glm::vec3(p[0], p[1], p[2]), glm::vec3(0.0f), glm::vec3(1.0f)));
                for (int c = 0; c < 3; ++c) out[c] = toUnorm8(encoded[c]);
                out[3] = toUnorm8(p[3]);
                break;
            }
            case VK_FORMAT_D32_SFLOAT:
            case VK_FORMAT_R32_SFLOAT:
                std::memcpy(out, p, 4);
                break;
            case VK_FORMAT_D16_UNORM: {
                const uint16_t value = uint16_t(std::lround(std::clamp(p[0], 0.0f, 1.0f) * 65535.0f));
                std::memcpy(out, &value, 2);
                break;
            }
            case VK_FORMAT_D24_UNORM_S8_UINT: {
                const uint32_t value = uint32_t(std::llround(double(std::clamp(p[0], 0.0f, 1.0f)) * 16777215.0));
                std::memcpy(out, &value, 4);
                break;
            }
            default:
                throw Error("cannot encode texels of " + formatName(format));
        }
    }
    return bytes;
}

HostImage decodeColorTexels(const uint8_t* bytes, uint32_t width, uint32_t height, VkFormat format) {
    HostImage image(width, height, 4);
    const size_t count = size_t(width) * height;
    for (size_t i = 0; i < count; ++i) {
        float* p = &image.pixels[i * 4];
        const uint8_t* in = bytes + i * bytesPerTexel(format);
        switch (format) {
            case VK_FORMAT_R16G16B16A16_SFLOAT:
                for (int c = 0; c < 4; ++c) {
                    uint16_t half;
                    std::memcpy(&half, in + 2 * c, 2);
                    p[c] = glm::unpackHalf1x16(half);
                }
                break;
            case VK_FORMAT_R32G32B32A32_SFLOAT:
                std::memcpy(p, in, 16);
                break;
            case VK_FORMAT_B10G11R11_UFLOAT_PACK32: {
                uint32_t packed;
                std::memcpy(&packed, in, 4);
                const glm::vec3 rgb = glm::unpackF2x11_1x10(packed);
                p[0] = rgb.x, p[1] = rgb.y, p[2] = rgb.z, p[3] = 1.0f;
                break;
            }
            case VK_FORMAT_R8G8B8A8_UNORM:
                for (int c = 0; c < 4; ++c) p[c] = in[c] / 255.0f;
                break;
            case VK_FORMAT_R8G8B8A8_SRGB: {
                const glm::vec3 linear = glm::convertSRGBToLinear(glm::vec3(in[0], in[1], in[2]) / 255.0f);
                p[0] = linear.x, p[1] = linear.y, p[2] = linear.z, p[3] = in[3] / 255.0f;
                break;
            }
            default:
                throw Error("cannot decode texels of " + formatName(format));
        }
    }
    return image;
}

}  // namespace ffxdof::vkrun
