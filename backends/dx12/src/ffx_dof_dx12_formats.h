// Which DXGI formats the D3D12 backend accepts for the engine's images, and the view formats it
// makes for them. Constexpr so that the rules are checked at compile time (tests/ in this folder).
//
// A view of format V can be made on a resource of format R when R == V or R is V's typeless
// family. That is why a depth buffer must be created typeless (R32_TYPELESS, not D32_FLOAT) to be
// sampled, and an sRGB output must be created typeless to get its UNORM UAV.
#pragma once

#include <dxgiformat.h>

namespace ffxdof::dx12 {

enum class ImageRole { Color, Depth, Output };

struct FormatRule {
    DXGI_FORMAT declared;  // what the engine passes to ffxDofGetResourceDX12
    DXGI_FORMAT family;    // the typeless format of its family (itself when there is none)
    DXGI_FORMAT srv;       // SRV format in the Color or Depth role; UNKNOWN: cannot be sampled in it
    DXGI_FORMAT uav;       // UAV format in the Output role; UNKNOWN: cannot be the output
    bool depth;            // the row is for the Depth role (the others are for Color and Output)
    bool srgb;             // data is sRGB-encoded: sampling decodes, the UNORM UAV needs encoding in shader
    const char* name;
};

// clang-format off
inline constexpr FormatRule kFormatRules[] = {
    // Color and output.
    {DXGI_FORMAT_R32G32B32A32_FLOAT,  DXGI_FORMAT_R32G32B32A32_TYPELESS, DXGI_FORMAT_R32G32B32A32_FLOAT,  DXGI_FORMAT_R32G32B32A32_FLOAT, false, false, "R32G32B32A32_FLOAT"},
    {DXGI_FORMAT_R16G16B16A16_FLOAT,  DXGI_FORMAT_R16G16B16A16_TYPELESS, DXGI_FORMAT_R16G16B16A16_FLOAT,  DXGI_FORMAT_R16G16B16A16_FLOAT, false, false, "R16G16B16A16_FLOAT"},
    {DXGI_FORMAT_R16G16B16A16_UNORM,  DXGI_FORMAT_R16G16B16A16_TYPELESS, DXGI_FORMAT_R16G16B16A16_UNORM,  DXGI_FORMAT_R16G16B16A16_UNORM, false, false, "R16G16B16A16_UNORM"},
    {DXGI_FORMAT_R11G11B10_FLOAT,     DXGI_FORMAT_R11G11B10_FLOAT,       DXGI_FORMAT_R11G11B10_FLOAT,     DXGI_FORMAT_R11G11B10_FLOAT,    false, false, "R11G11B10_FLOAT"},
    {DXGI_FORMAT_R10G10B10A2_UNORM,   DXGI_FORMAT_R10G10B10A2_TYPELESS,  DXGI_FORMAT_R10G10B10A2_UNORM,   DXGI_FORMAT_R10G10B10A2_UNORM,  false, false, "R10G10B10A2_UNORM"},
    {DXGI_FORMAT_R8G8B8A8_UNORM,      DXGI_FORMAT_R8G8B8A8_TYPELESS,     DXGI_FORMAT_R8G8B8A8_UNORM,      DXGI_FORMAT_R8G8B8A8_UNORM,     false, false, "R8G8B8A8_UNORM"},
    {DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, DXGI_FORMAT_R8G8B8A8_TYPELESS,     DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, DXGI_FORMAT_R8G8B8A8_UNORM,     false, true,  "R8G8B8A8_UNORM_SRGB"},
    {DXGI_FORMAT_B8G8R8A8_UNORM,      DXGI_FORMAT_B8G8R8A8_TYPELESS,     DXGI_FORMAT_B8G8R8A8_UNORM,      DXGI_FORMAT_B8G8R8A8_UNORM,     false, false, "B8G8R8A8_UNORM"},
    {DXGI_FORMAT_B8G8R8A8_UNORM_SRGB, DXGI_FORMAT_B8G8R8A8_TYPELESS,     DXGI_FORMAT_B8G8R8A8_UNORM_SRGB, DXGI_FORMAT_B8G8R8A8_UNORM,     false, true,  "B8G8R8A8_UNORM_SRGB"},
    {DXGI_FORMAT_R9G9B9E5_SHAREDEXP,  DXGI_FORMAT_R9G9B9E5_SHAREDEXP,    DXGI_FORMAT_R9G9B9E5_SHAREDEXP,  DXGI_FORMAT_UNKNOWN,            false, false, "R9G9B9E5_SHAREDEXP"},
    // Depth: the depth format, its typeless family or its SRV format may be declared; all sample the
    // depth plane (plane 0) through the SRV format.
    {DXGI_FORMAT_D32_FLOAT,                DXGI_FORMAT_R32_TYPELESS,      DXGI_FORMAT_R32_FLOAT,                DXGI_FORMAT_UNKNOWN, true, false, "D32_FLOAT"},
    {DXGI_FORMAT_R32_TYPELESS,             DXGI_FORMAT_R32_TYPELESS,      DXGI_FORMAT_R32_FLOAT,                DXGI_FORMAT_UNKNOWN, true, false, "R32_TYPELESS"},
    {DXGI_FORMAT_R32_FLOAT,                DXGI_FORMAT_R32_TYPELESS,      DXGI_FORMAT_R32_FLOAT,                DXGI_FORMAT_UNKNOWN, true, false, "R32_FLOAT"},
    {DXGI_FORMAT_D24_UNORM_S8_UINT,        DXGI_FORMAT_R24G8_TYPELESS,    DXGI_FORMAT_R24_UNORM_X8_TYPELESS,    DXGI_FORMAT_UNKNOWN, true, false, "D24_UNORM_S8_UINT"},
    {DXGI_FORMAT_R24G8_TYPELESS,           DXGI_FORMAT_R24G8_TYPELESS,    DXGI_FORMAT_R24_UNORM_X8_TYPELESS,    DXGI_FORMAT_UNKNOWN, true, false, "R24G8_TYPELESS"},
    {DXGI_FORMAT_R24_UNORM_X8_TYPELESS,    DXGI_FORMAT_R24G8_TYPELESS,    DXGI_FORMAT_R24_UNORM_X8_TYPELESS,    DXGI_FORMAT_UNKNOWN, true, false, "R24_UNORM_X8_TYPELESS"},
    {DXGI_FORMAT_D16_UNORM,                DXGI_FORMAT_R16_TYPELESS,      DXGI_FORMAT_R16_UNORM,                DXGI_FORMAT_UNKNOWN, true, false, "D16_UNORM"},
    {DXGI_FORMAT_R16_TYPELESS,             DXGI_FORMAT_R16_TYPELESS,      DXGI_FORMAT_R16_UNORM,                DXGI_FORMAT_UNKNOWN, true, false, "R16_TYPELESS"},
    {DXGI_FORMAT_R16_UNORM,                DXGI_FORMAT_R16_TYPELESS,      DXGI_FORMAT_R16_UNORM,                DXGI_FORMAT_UNKNOWN, true, false, "R16_UNORM"},
    {DXGI_FORMAT_D32_FLOAT_S8X24_UINT,     DXGI_FORMAT_R32G8X24_TYPELESS, DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS, DXGI_FORMAT_UNKNOWN, true, false, "D32_FLOAT_S8X24_UINT"},
    {DXGI_FORMAT_R32G8X24_TYPELESS,        DXGI_FORMAT_R32G8X24_TYPELESS, DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS, DXGI_FORMAT_UNKNOWN, true, false, "R32G8X24_TYPELESS"},
    {DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS, DXGI_FORMAT_R32G8X24_TYPELESS, DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS, DXGI_FORMAT_UNKNOWN, true, false, "R32_FLOAT_X8X24_TYPELESS"},
};
// clang-format on

// The rule for a declared format in a role, or nullptr when the format is not accepted in it.
constexpr const FormatRule* findFormatRule(DXGI_FORMAT declared, ImageRole role) {
    for (const FormatRule& rule : kFormatRules) {
        if (rule.declared != declared || rule.depth != (role == ImageRole::Depth)) continue;
        const DXGI_FORMAT view = role == ImageRole::Output ? rule.uav : rule.srv;
        return view == DXGI_FORMAT_UNKNOWN ? nullptr : &rule;
    }
    return nullptr;
}

// The format the backend views the image with in a role; UNKNOWN when not accepted.
constexpr DXGI_FORMAT viewFormat(DXGI_FORMAT declared, ImageRole role) {
    const FormatRule* rule = findFormatRule(declared, role);
    if (rule == nullptr) return DXGI_FORMAT_UNKNOWN;
    return role == ImageRole::Output ? rule->uav : rule->srv;
}

// True when a view of format `view` (of `rule`'s family) can be made on a resource created with
// `resourceFormat` without relaxed format casting.
constexpr bool viewableOn(const FormatRule& rule, DXGI_FORMAT view, DXGI_FORMAT resourceFormat) {
    return resourceFormat == view || resourceFormat == rule.family;
}

// A readable name for error messages ("DXGI_FORMAT 42" style fallback is done by the caller).
constexpr const char* formatName(DXGI_FORMAT format) {
    for (const FormatRule& rule : kFormatRules) {
        if (rule.declared == format) return rule.name;
    }
    return nullptr;
}

}  // namespace ffxdof::dx12
