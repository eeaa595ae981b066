// Near and far highlights drawn at full resolution: the one place that decides which light the half-res layers
// leave out and how the composite draws it (see docs/technique.md, "Far highlights" and "Near highlights").
//
// The half-res layers are upsampled bilinearly, so a far disc's rim spreads over one more half-res texel
// (2 full-res px) than the disc: a point's disc kept 0.09 to 0.16 of its level 1.5 px beyond its radius,
// and brighter than display white it looked wider than the thin lens's, with coloured fringes
// (docs/quality.md, point discs and far-highlights). Pass 2 therefore takes the light of pixels far brighter
// than the dimmest far pixel of their tile out of the half-res colour, down to that level, and stores it per
// tile (HIGHLIGHTS: where it lies, its radius, its spread, its energy); the composite draws each such light as a disc
// of the aperture's shape at full resolution, its energy over the disc's area, behind whatever lies in front of it.
// Energy leaves the layers only where a slot holds it, so nothing is lost or drawn twice. Near lights take the same
// path over a floor of their own (ffxDofPackHighlightFloors), and the composite draws them over everything.
//
// A tile has FFX_DOF_HIGHLIGHT_SLOTS slots, one per quadrant of 8 x 8 full-res px: a slot holds the light of
// every quad of its quadrant that gives some, as its light-weighted centre, the axis along which its light
// spreads most and its spread across it. It is drawn as two discs, half its light each, at the ends of that
// axis (one disc where the light spreads alike every way), each with a rim as wide as the spread across. One
// light of a few pixels is drawn where it lies, and so are two lights a few pixels apart in one quadrant; three
// or more there are drawn as two.
#ifndef FFX_DOF_HIGHLIGHTS_H
#define FFX_DOF_HIGHLIGHTS_H

#include "ffx_dof_common.h"

#if FFX_DOF_HIGHLIGHT_SLOTS != 4
#error "a tile's highlight slots are its four quadrants"
#endif

// A quad pixel gives light to the full-resolution path from this luminance on (display white, in the
// input's units), fully from twice it: below white a soft rim costs little the eye sees.
#define FFX_DOF_HIGHLIGHT_MIN_LUMINANCE 1.0f
// That luminance in the units of the input scaled by `scale` (ffxDofColorRangeScale), as pass 2 and the composite see
// it.
FFX_DOF_INLINE FfxFloat32 ffxDofHighlightWhite(FfxFloat32 scale) { return FFX_DOF_HIGHLIGHT_MIN_LUMINANCE * scale; }
// ... and where it is at least this many times as bright as its floor, the dimmest far pixel of its tile and
// the tile's border (fully from twice it): the contrast of a light against what lies around it.
#define FFX_DOF_HIGHLIGHT_CONTRAST 2.0f
// ... and where its far radius (half-res px) is above FFX_DOF_HIGHLIGHT_MIN_RADIUS, fully from
// FFX_DOF_HIGHLIGHT_FULL_RADIUS. Below that the composite draws a pixel's light at full resolution alone (its
// own-surface and small-source gathers, ffx_dof_small_sources.h), so the two full-resolution paths may share
// a light there; from it on the half-res layers take part of what those gathers leave (ffxDofOwnGatherShare
// falls from 1 at 2 to 0 at FFX_DOF_FAR_LAYER_ONLY_RADIUS), and so the highlights take all of a bright
// pixel's light above its floor from there. Ramped in from 3 to 4 instead, a point at 2.25 and 3 half-res px
// drew a quarter and all of its light through the layers, whose bilinear upsample left a glow of 0.04 and
// 0.12 of the disc's level beyond its rim (docs/quality.md, point discs).
#define FFX_DOF_HIGHLIGHT_MIN_RADIUS 1.5f
#define FFX_DOF_HIGHLIGHT_FULL_RADIUS 2.0f
// The same for near pixels (radius above FFX_DOF_NEAR_HIGHLIGHT_MIN_RADIUS, fully from
// FFX_DOF_NEAR_HIGHLIGHT_FULL_RADIUS): the near layer, upsampled bilinearly from half resolution and
// post-filtered over 3 x 3 texels, drew a near point's disc 1.3 to 1.9 px smaller than the thin lens's, with a
// glow of 0.04 to 0.14 of its level beyond its rim (docs/quality.md, near point discs). The composite's
// gathers of a near pixel's own surface below FFX_DOF_FAR_LAYER_ONLY_RADIUS read what pass 2 left of each
// pixel (ffxDofPixelHighlightShare), as for far pixels, so near lights may start lower.
#define FFX_DOF_NEAR_HIGHLIGHT_MIN_RADIUS 1.0f
#define FFX_DOF_NEAR_HIGHLIGHT_FULL_RADIUS 1.5f
#define FFX_DOF_SQRT2 1.41421356f
// The widest rim a highlight's disc is drawn with (full-res px): half of it reaches beyond the radius, within the
// margins of dilate (FFX_DOF_DILATE_MARGIN, 6 full-res px) and of the composite's window (ffxDofHighlightTileRange).
// A quadrant of uniform light (8 x 8 px: a spread of 3.3 px, a rim of 9.2) at a small radius is drawn as one disc
// per quadrant, and such discs 8 px apart sum to a flat patch only where their rims overlap: at 6 px a bright near
// patch of 24 x 24 px at radius 2 half-res px rippled by 10% inside (docs/technique.md, "Near highlights").
#define FFX_DOF_HIGHLIGHT_MAX_RIM_WIDTH 9.0f

// ---- Which light a quad gives --------------------------------------------------------------------

// How much of its light a pixel of radius `coc` (half-res px) may give by its radius: far pixels from
// FFX_DOF_HIGHLIGHT_MIN_RADIUS, near ones from FFX_DOF_NEAR_HIGHLIGHT_MIN_RADIUS, each ramped in.
FFX_DOF_INLINE FfxFloat32 ffxDofHighlightRadiusRamp(FfxFloat32 coc)
{
    return coc < 0.0f
               ? ffxDofSaturate((-coc - FFX_DOF_HIGHLIGHT_MIN_RADIUS) *
                                (1.0f / (FFX_DOF_HIGHLIGHT_FULL_RADIUS - FFX_DOF_HIGHLIGHT_MIN_RADIUS)))
               : ffxDofSaturate((coc - FFX_DOF_NEAR_HIGHLIGHT_MIN_RADIUS) *
                                (1.0f / (FFX_DOF_NEAR_HIGHLIGHT_FULL_RADIUS - FFX_DOF_NEAR_HIGHLIGHT_MIN_RADIUS)));
}

// The share of its light a quad pixel of luminance `luminance` and radius `coc` gives to the full-resolution
// path (`scale`: the colour scale of the HDR range), over a floor and among a surround (`floorAndSurround`,
// ffxDofHighlightFloor): what lies above the floor, where the pixel is far brighter than the surround, ramped in by
// the thresholds above so that a light crossing one changes continuously.
//
// The two differ for far pixels. What a far light gives is what it has above the dimmest far pixel around it (the
// far field behind it), but whether it is a light at all is told by the far field's mean: a bright region that
// fills much of a tile is that far field, not a light. Judged against the dimmest pixel alone, a sky above white
// behind dark branches gave its light to the quadrants' discs wherever a branch darkened a tile, and each disc,
// drawn behind the branch and hidden by it whole or not at all, left the branch's veil up to half as bright as the
// thin lens's, with steps at the quadrants' borders (docs/quality.md, far-branches). Against the mean a light needs
// twice the tile's mean luminance, which a region covering half of it never has; a light of a few pixels raises the
// mean by its light over the tile's 324 pixels. Taken above the mean as well, a light lying across tiles of
// different means split between the two paths unevenly, and issue 17's square lights kept 0.96 to 1.02 of their
// energy instead of 1.00 (docs/technique.md, "A bright far field is not a light").
// How far above display white a pixel of this luminance is, from 0 at white to 1 at twice it: the first factor of
// ffxDofHighlightShare, so a pixel where it is 0 gives no light whatever its floors (pass 2 reads the floors only in
// waves with a pixel above white).
FFX_DOF_INLINE FfxFloat32 ffxDofHighlightBrightness(FfxFloat32 luminance, FfxFloat32 scale)
{
    return ffxDofSaturate(luminance / ffxDofHighlightWhite(scale) - 1.0f);
}
FFX_DOF_INLINE FfxFloat32 ffxDofHighlightShare(FfxFloat32 luminance, FfxFloat32 coc, FfxFloat32x2 floorAndSurround,
                                               FfxFloat32 scale)
{
    if (!(luminance > 0.0f))
        return 0.0f;
    FfxFloat32 floorLuminance = floorAndSurround.x;
    FfxFloat32 surround = max(floorAndSurround.y, floorLuminance);
    FfxFloat32 bright = ffxDofHighlightBrightness(luminance, scale);
    FfxFloat32 contrast = ffxDofSaturate(luminance / max(FFX_DOF_HIGHLIGHT_CONTRAST * surround, 1e-30f) - 1.0f);
    return bright * contrast * ffxDofHighlightRadiusRamp(coc) * ffxDofSaturate(1.0f - floorLuminance / luminance);
}

// A tile's floors: far pixels stand on the dimmest far pixel of the tile and its border (what lies behind a far
// light is the far field around it) among the mean far luminance there (the surround, ffxDofHighlightShare); near
// pixels on the dimmest pixel of any kind there (a near light stands in front of whatever lies around it: an
// in-focus wall holds no far pixel), among the larger of that and the far surround (ffxDofHighlightFloor). Stored in
// one word of HIGHLIGHTS, 10 bits each (far floor, near floor, far surround; bit 30 FFX_DOF_HIGHLIGHT_GIVEN_BIT, bit
// 31 free), and pass 2 gives light over the floors as stored, so that the composite, which reads them back, takes the
// same shares to the bit.
// FFX_DOF_HIGHLIGHT_NO_FLOOR, the largest half, over which no pixel gives light (the HDR range keeps them at
// FFX_DOF_COLOR_RANGE_LIMIT): none of that kind there.
#define FFX_DOF_HIGHLIGHT_NO_FLOOR 65504.0f
// A floor in 10 bits: an unsigned float of 5 exponent and 5 mantissa bits (as B10G11R11's blue), its mantissa cut
// (a floor lowered by less than 1/32); below 2^-14 it is 0, and FFX_DOF_HIGHLIGHT_NO_FLOOR and above take the code
// of all ones (every code of exponent 31 reads as FFX_DOF_HIGHLIGHT_NO_FLOOR). Decoded from its bits alone: no rounding
// of any device's arithmetic in between.
#define FFX_DOF_HIGHLIGHT_FLOOR_BITS 10u
#define FFX_DOF_HIGHLIGHT_FLOOR_MASK 0x3ffu
#define FFX_DOF_HIGHLIGHT_SMALLEST_FLOOR 6.103515625e-5f
FFX_DOF_INLINE FfxUInt32 ffxDofEncodeHighlightFloor(FfxFloat32 value)
{
    if (!(value < FFX_DOF_HIGHLIGHT_NO_FLOOR))
        return FFX_DOF_HIGHLIGHT_FLOOR_MASK;
    if (!(value >= FFX_DOF_HIGHLIGHT_SMALLEST_FLOOR))
        return 0u;
    FfxUInt32 bits = ffxDofAsUInt(value);
    // The float's biased exponent (127) less 112 is the 10-bit float's (15): 1 to 30 over the range kept.
    return ((((bits >> 23u) & 0xffu) - 112u) << 5u) | ((bits >> 18u) & 31u);
}
FFX_DOF_INLINE FfxFloat32 ffxDofDecodeHighlightFloor(FfxUInt32 code)
{
    FfxUInt32 exponent = code >> 5u;
    if (exponent == 31u)
        return FFX_DOF_HIGHLIGHT_NO_FLOOR;
    return exponent == 0u ? 0.0f : ffxDofAsFloat(((exponent + 112u) << 23u) | ((code & 31u) << 18u));
}
// (far floor, near floor, far surround) to their word and back.
FFX_DOF_INLINE FfxUInt32 ffxDofPackHighlightFloors(FfxFloat32x3 floors)
{
    return ffxDofEncodeHighlightFloor(floors.x) |
           (ffxDofEncodeHighlightFloor(floors.y) << FFX_DOF_HIGHLIGHT_FLOOR_BITS) |
           (ffxDofEncodeHighlightFloor(floors.z) << (2u * FFX_DOF_HIGHLIGHT_FLOOR_BITS));
}
FFX_DOF_INLINE FfxFloat32x3 ffxDofUnpackHighlightFloors(FfxUInt32 word)
{
    return FfxFloat32x3(
        ffxDofDecodeHighlightFloor(word & FFX_DOF_HIGHLIGHT_FLOOR_MASK),
        ffxDofDecodeHighlightFloor((word >> FFX_DOF_HIGHLIGHT_FLOOR_BITS) & FFX_DOF_HIGHLIGHT_FLOOR_MASK),
        ffxDofDecodeHighlightFloor((word >> (2u * FFX_DOF_HIGHLIGHT_FLOOR_BITS)) & FFX_DOF_HIGHLIGHT_FLOOR_MASK));
}
// The mean of the far luminances (sum, count) of a tile and its border, or 0 without any: the far surround.
FFX_DOF_INLINE FfxFloat32 ffxDofFarSurround(FfxFloat32x2 farLuminanceSum)
{
    return farLuminanceSum.y > 0.0f ? farLuminanceSum.x / farLuminanceSum.y : 0.0f;
}

// ---- A bright far field behind nearer far content ------------------------------------------------

// A sky brighter than display white seen between dark far branches nearer than it: where the branches cover more than
// half of a tile, the sky there is twice the tile's mean and gives light, and every tile its discs reach drew those
// discs at full resolution: the composite of the scene far-branches took 3.2 times the floor's (docs/technique.md, "A
// bright far field behind nearer far content"). A light lies in front of what surrounds it, or at its depth; a bright
// far field showing through nearer far content lies behind it. So a tile gives no far light where its far pixels
// above white cover at least FFX_DOF_BRIGHT_FIELD_MIN_SHARE of its far pixels (and its border's) and lie on average
// more than FFX_DOF_BRIGHT_FIELD_DEPTH_GAP half-res px of radius behind the other far pixels: a light of up to 4 x 4
// px behind branches stays a light.
#define FFX_DOF_BRIGHT_FIELD_MIN_SHARE 0.0625f
#define FFX_DOF_BRIGHT_FIELD_DEPTH_GAP 1.0f
// What a pixel of (luminance, radius) `rimSample` adds to its tile's far sums, (luminance, count, radius, count above
// white), all 0 where it is not in the far field: the far surround (ffxDofFarSurround, from the first two) and whether
// the tile is a bright far field behind nearer far content (ffxDofBrightFieldBehind, with the radii of the pixels
// above white, each `unclampedCoc` times its w). `white`: display white in the scaled input's units
// (ffxDofHighlightWhite). The radius is taken before the limit clamps it (`unclampedCoc`): far branches and the sky
// behind them often share the limit's radius.
FFX_DOF_INLINE FfxFloat32x4 ffxDofFarSums(FfxFloat32x2 rimSample, FfxFloat32 unclampedCoc, FfxFloat32 white)
{
    if (!(rimSample.y <= -FFX_DOF_IN_FOCUS_RADIUS))
        return FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
    return FfxFloat32x4(rimSample.x, 1.0f, unclampedCoc, rimSample.x > white ? 1.0f : 0.0f);
}
// Whether a tile of far sums `farSums` (ffxDofFarSums), whose pixels above white have radii summing to
// `brightRadiusSum`, is a bright far field behind nearer far content, which gives no far light.
FFX_DOF_INLINE FfxBoolean ffxDofBrightFieldBehind(FfxFloat32x4 farSums, FfxFloat32 brightRadiusSum)
{
    FfxFloat32 brightCount = farSums.w;
    FfxFloat32 otherCount = farSums.y - brightCount;
    if (!(brightCount > 0.0f && otherCount > 0.0f) || brightCount < FFX_DOF_BRIGHT_FIELD_MIN_SHARE * farSums.y)
        return false;
    return brightRadiusSum / brightCount < (farSums.z - brightRadiusSum) / otherCount - FFX_DOF_BRIGHT_FIELD_DEPTH_GAP;
}

// Set in a tile's word of floors where its pixels gave light (a slot of the tile holds some): dilate and the composite
// tell from this one bit, not from the colour peak, which tiles' highlights are drawn. A sky above white behind dark
// branches gives none (ffxDofHighlightShare), and judged by its peak every tile such a tile's discs could reach
// took the composite's full-resolution path and the blur's finer MIP: the scene's composite took 3.6 and its blur
// 1.9 times as long as without (docs/performance.md, "A sky above white takes the cheap paths").
#define FFX_DOF_HIGHLIGHT_GIVEN_BIT 0x40000000u
FFX_DOF_INLINE FfxBoolean ffxDofHighlightFloorsGaveLight(FfxUInt32 word)
{
    return (word & FFX_DOF_HIGHLIGHT_GIVEN_BIT) != 0u;
}

// The word of a tile whose pixels give no light (ffxDofTileMayHoldHighlights false, or none gave any).
FFX_DOF_INLINE FfxUInt32 ffxDofNoHighlightFloors()
{
    return ffxDofPackHighlightFloors(
        FfxFloat32x3(FFX_DOF_HIGHLIGHT_NO_FLOOR, FFX_DOF_HIGHLIGHT_NO_FLOOR, FFX_DOF_HIGHLIGHT_NO_FLOOR));
}
// The floor and surround a pixel of radius `coc` stands on and among. A near pixel's surround is its floor, or the
// far surround where that is larger: the anti-aliased rim of a dark near leaf against a sky above white holds the sky's
// colour at the leaf's depth, 20 to 30 times the leaf's own luminance, and every such pixel above white was a near
// highlight (the composite of the scene near-leaves-sky at 1080p took 1.14 to 1.19 times as long, and drew the same;
// docs/technique.md, "A near pixel among a bright far field"). A near light is still one where it is far brighter than
// the far field it lies over.
FFX_DOF_INLINE FfxFloat32x2 ffxDofHighlightFloor(FfxFloat32x3 floors, FfxFloat32 coc)
{
    return coc > 0.0f ? FfxFloat32x2(floors.y, max(floors.y, floors.z)) : FfxFloat32x2(floors.x, floors.z);
}

// Whether the image's edge cuts the quad of full-res pixel `pixel`: such a quad repeats its edge pixels, which
// stay in the layers (pass 2 gives no light of it, and the composite takes none).
FFX_DOF_INLINE FfxBoolean ffxDofQuadCutByEdge(FfxUInt32x2 pixel, FfxUInt32x2 fullSize)
{
    return (pixel.x | 1u) >= fullSize.x || (pixel.y | 1u) >= fullSize.y;
}

// ffxDofHighlightShare of full-res pixel `pixel` of scaled colour `color` and radius `coc` (half-res px) in a
// tile of floors `floors` (ffxDofUnpackHighlightFloors), as pass 2 takes it (but for the radius: pass 2 gives a light's
// anti-aliased rim pixels the light's radius, ffxDofLightRimCocInQuad, which needs their neighbours; the two differ
// only where one of the radii lies below FFX_DOF_HIGHLIGHT_FULL_RADIUS): none where the image's edge cuts the pixel's
// quad (its edge pixels repeated stay in the layers). What the composite's full-resolution gathers leave of a pixel's
// light, the rest being drawn as a highlight.
FFX_DOF_INLINE FfxFloat32 ffxDofPixelHighlightShare(FfxUInt32x2 pixel, FfxFloat32x3 color, FfxFloat32 coc,
                                                    FfxFloat32x3 floors, FfxFloat32 scale, FfxUInt32x2 fullSize)
{
    if (ffxDofQuadCutByEdge(pixel, fullSize))
        return 0.0f;
    return ffxDofHighlightShare(ffxDofLuminance32(color), coc, ffxDofHighlightFloor(floors, coc), scale);
}

// A light of the full-resolution path: where it lies (full-res px from its tile's top-left corner), its
// radius (|CoC|, half-res px) and whether it is near, its axis (from where it lies to each of its two discs: the square
// root of its light's variance along its principal axis less that across, full-res px), how far its light spreads about
// that axis (the root mean square distance of what is left, full-res px) and its energy (colour summed over its
// pixels, in the HDR range's units). Two equal points g px apart have an axis of g / 2 and no spread; a round
// light of radius a no axis and a spread of a / sqrt(2).
struct FfxDofHighlight
{
    FfxFloat32x2 position;
    FfxFloat32 radius;
    FfxBoolean near;
    FfxFloat32x2 axis;
    FfxFloat32 spread;
    FfxFloat32x3 energy;
};

// A highlight as sums over the quads it gathers (a quadrant of a tile: every quad that gives light there, so
// that a light is never split between the paths): energy (xyz) and light (w, luminance x share); the
// light-weighted position (xy), |radius| (z) and squared distance from the tile's corner (w); the
// light-weighted x^2 - y^2 and 2 x y of the position (its second moments' part that has a direction); and the
// light of its near pixels.
struct FfxDofHighlightSums
{
    FfxFloat32x4 energyLight;
    FfxFloat32x4 placeRadius;
    FfxFloat32x2 anisotropy;
    FfxFloat32 nearLight;
};

// What a quad gives: the light of its pixels 0..3 (top-left, top-right, bottom-left, bottom-right) at
// `shares` (ffxDofHighlightShare), `inTile` the quad's top-left pixel in its tile (full-res px).
FFX_DOF_INLINE FfxDofHighlightSums ffxDofQuadHighlightSums(FfxFloat32x3 color0, FfxFloat32x3 color1,
                                                           FfxFloat32x3 color2, FfxFloat32x3 color3, FfxFloat32x4 cocs,
                                                           FfxFloat32x4 shares, FfxFloat32x2 inTile)
{
    FfxFloat32x4 light = shares * FfxFloat32x4(ffxDofLuminance32(color0), ffxDofLuminance32(color1),
                                               ffxDofLuminance32(color2), ffxDofLuminance32(color3));
    FfxFloat32x2 centre0 = inTile + FfxFloat32x2(0.5f, 0.5f);
    FfxFloat32x2 centre3 = centre0 + FfxFloat32x2(1.0f, 1.0f);
    // Squared distances of the four pixel centres from the tile's corner, and x^2 - y^2 and 2 x y of each.
    FfxFloat32x4 distance2 = FfxFloat32x4(dot(centre0, centre0), centre3.x * centre3.x + centre0.y * centre0.y,
                                          centre0.x * centre0.x + centre3.y * centre3.y, dot(centre3, centre3));
    FfxFloat32x4 squareDifference =
        FfxFloat32x4(centre0.x * centre0.x - centre0.y * centre0.y, centre3.x * centre3.x - centre0.y * centre0.y,
                     centre0.x * centre0.x - centre3.y * centre3.y, centre3.x * centre3.x - centre3.y * centre3.y);
    FfxFloat32x4 twiceProduct =
        2.0f * FfxFloat32x4(centre0.x * centre0.y, centre3.x * centre0.y, centre0.x * centre3.y, centre3.x * centre3.y);
    FfxFloat32 lightSum = light.x + light.y + light.z + light.w;
    FfxDofHighlightSums sums;
    sums.energyLight =
        FfxFloat32x4(color0 * shares.x + color1 * shares.y + color2 * shares.z + color3 * shares.w, lightSum);
    sums.placeRadius = FfxFloat32x4(centre0 * lightSum + FfxFloat32x2(light.y + light.w, light.z + light.w),
                                    dot(abs(cocs), light), dot(distance2, light));
    sums.anisotropy = FfxFloat32x2(dot(squareDifference, light), dot(twiceProduct, light));
    FfxFloat32x4 nearPixels = FfxFloat32x4(cocs.x > 0.0f ? 1.0f : 0.0f, cocs.y > 0.0f ? 1.0f : 0.0f,
                                           cocs.z > 0.0f ? 1.0f : 0.0f, cocs.w > 0.0f ? 1.0f : 0.0f);
    sums.nearLight = dot(nearPixels, light);
    return sums;
}

FFX_DOF_INLINE FfxDofHighlightSums ffxDofAddHighlightSums(FfxDofHighlightSums a, FfxDofHighlightSums b)
{
    FfxDofHighlightSums sums;
    sums.energyLight = a.energyLight + b.energyLight;
    sums.placeRadius = a.placeRadius + b.placeRadius;
    sums.anisotropy = a.anisotropy + b.anisotropy;
    sums.nearLight = a.nearLight + b.nearLight;
    return sums;
}

// The sums of pixels that give no light.
FFX_DOF_INLINE FfxDofHighlightSums ffxDofNoHighlightSums()
{
    FfxDofHighlightSums sums;
    sums.energyLight = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
    sums.placeRadius = FfxFloat32x4(0.0f, 0.0f, 0.0f, 0.0f);
    sums.anisotropy = FfxFloat32x2(0.0f, 0.0f);
    sums.nearLight = 0.0f;
    return sums;
}

// Whether the sums hold light.
FFX_DOF_INLINE FfxBoolean ffxDofHighlightSumsHoldLight(FfxDofHighlightSums sums) { return sums.energyLight.w > 0.0f; }

// The highlight the sums describe (where they hold light).
FFX_DOF_INLINE FfxDofHighlight ffxDofFinishHighlight(FfxDofHighlightSums sums)
{
    FfxDofHighlight highlight;
    FfxFloat32 inverseLight = 1.0f / sums.energyLight.w;
    highlight.energy = FfxFloat32x3(sums.energyLight.x, sums.energyLight.y, sums.energyLight.z);
    highlight.position = FfxFloat32x2(sums.placeRadius.x, sums.placeRadius.y) * inverseLight;
    highlight.radius = sums.placeRadius.z * inverseLight;
    // A quadrant with near and far light (a near speck over a far light within 8 px) is drawn as the side with
    // more of it: its light is kept, the other side's radius and occlusion are not.
    highlight.near = 2.0f * sums.nearLight > sums.energyLight.w;
    FfxFloat32x2 centre = highlight.position;
    // The covariance's trace (the variance summed over both axes) and its part with a direction, (c_xx - c_yy,
    // 2 c_xy), whose length is the variance along the principal axis less that across it.
    FfxFloat32 variance = max(sums.placeRadius.w * inverseLight - dot(centre, centre), 0.0f);
    FfxFloat32x2 anisotropy = sums.anisotropy * inverseLight -
                              FfxFloat32x2(centre.x * centre.x - centre.y * centre.y, 2.0f * centre.x * centre.y);
    FfxFloat32 excess = min(length(anisotropy), variance);
    // A light that spreads alike every way but for rounding is one disc (its axis would be a few hundredths of
    // its spread).
    excess = excess > 1e-3f * variance ? excess : 0.0f;
    // The principal axis halves the angle of (c_xx - c_yy, 2 c_xy).
    FfxFloat32x2 bisector = anisotropy + FfxFloat32x2(length(anisotropy), 0.0f);
    FfxFloat32x2 direction =
        dot(bisector, bisector) > 1e-12f ? bisector * (1.0f / length(bisector)) : FfxFloat32x2(0.0f, 1.0f);
    highlight.axis = direction * sqrt(excess);
    highlight.spread = sqrt(variance - excess);
    return highlight;
}

// Where disc `disc` (0 or 1) of a highlight lies (full-res px from its tile's corner): the ends of its axis,
// kept within the tile (whose light it holds: so that dilate's margin and the composite's window cover its reach).
FFX_DOF_INLINE FfxFloat32x2 ffxDofHighlightDiscCentre(FfxDofHighlight highlight, FfxUInt32 disc)
{
    FfxFloat32 tileSide = 2.0f * FfxFloat32(FFX_DOF_TILE_SIZE);
    return clamp(highlight.position + (disc == 0u ? highlight.axis : -highlight.axis), FfxFloat32x2(0.0f, 0.0f),
                 FfxFloat32x2(tileSide, tileSide));
}

// How many discs a highlight is drawn as: one where its light spreads alike every way (its two would coincide).
FFX_DOF_INLINE FfxUInt32 ffxDofHighlightDiscCount(FfxDofHighlight highlight)
{
    return highlight.axis.x != 0.0f || highlight.axis.y != 0.0f ? 2u : 1u;
}

// ---- Storage: two words a slot, zero for an empty one ---------------------------------------------

// RGB9E5: three 9-bit mantissas and a shared exponent (bias 15), as VK_FORMAT_E5B9G9R9_UFLOAT_PACK32 stores it
// (largest value 65408; the HDR range keeps a pixel at most FFX_DOF_COLOR_RANGE_LIMIT, four of them 16384).
// Rounded to nearest, so the energy drawn is within 1/512 of what left the layers.
#define FFX_DOF_RGB9E5_MAX 65408.0f
FFX_DOF_INLINE FfxUInt32 ffxDofPackRgb9e5(FfxFloat32x3 color)
{
    FfxFloat32x3 clamped = clamp(color, FfxFloat32x3(0.0f, 0.0f, 0.0f),
                                 FfxFloat32x3(FFX_DOF_RGB9E5_MAX, FFX_DOF_RGB9E5_MAX, FFX_DOF_RGB9E5_MAX));
    FfxFloat32 largest = max(clamped.x, max(clamped.y, clamped.z));
    // The exponent of the largest channel from its bits (exact, unlike log2), at least the format's smallest.
    FfxInt32 exponent = max(FfxInt32((ffxDofAsUInt(largest) >> 23u) & 0xffu) - 127, -16) + 1;
    FfxFloat32 step = ffxDofAsFloat(FfxUInt32(exponent - 9 + 127) << 23u);
    // Rounding can carry the largest mantissa to 512: one exponent more.
    if (floor(largest / step + 0.5f) >= 512.0f)
    {
        exponent += 1;
        step *= 2.0f;
    }
    FfxUInt32x3 mantissa = FfxUInt32x3(floor(clamped / step + FfxFloat32x3(0.5f, 0.5f, 0.5f)));
    return mantissa.x | (mantissa.y << 9u) | (mantissa.z << 18u) | (FfxUInt32(exponent + 15) << 27u);
}
FFX_DOF_INLINE FfxFloat32x3 ffxDofUnpackRgb9e5(FfxUInt32 bits)
{
    FfxFloat32 step = ffxDofAsFloat(FfxUInt32(FfxInt32(bits >> 27u) - 15 - 9 + 127) << 23u);
    return FfxFloat32x3(FfxFloat32(bits & 0x1ffu), FfxFloat32((bits >> 9u) & 0x1ffu),
                        FfxFloat32((bits >> 18u) & 0x1ffu)) *
           step;
}

// Word 0: the energy in units of FFX_DOF_HIGHLIGHT_ENERGY_UNIT (RGB9E5; 0 only for an empty slot, since a stored
// light keeps a nonzero mantissa): a quadrant's 64 pixels of at most FFX_DOF_COLOR_RANGE_LIMIT (4096, the HDR
// range) sum to 2^18, beyond the format's 65408, which clamped a patch of 16,400 to half its energy.
#define FFX_DOF_HIGHLIGHT_ENERGY_UNIT 16.0f
// Word 1: the position in quarters of a pixel (6 bits each way: a tile is 16 px), the radius in 32nds of a
// half-res px (12 bits, up to 128) and the spread in 16ths of a pixel (8 bits, up to 16). Word 2: the axis in
// quarters of a pixel, two signed bytes (up to 31.75 px each way; its discs stay within the tile), and in bit 16
// whether the light is near.
#define FFX_DOF_HIGHLIGHT_POSITION_STEPS 4.0f
#define FFX_DOF_HIGHLIGHT_NEAR_BIT 0x10000u
#define FFX_DOF_HIGHLIGHT_RADIUS_STEPS 32.0f
#define FFX_DOF_HIGHLIGHT_SPREAD_STEPS 16.0f
#if FFX_DOF_HIGHLIGHT_WORDS != 3
#error "a highlight is three words: its energy, its place, radius and spread, and its axis"
#endif
FFX_DOF_INLINE FfxUInt32x3 ffxDofPackHighlight(FfxDofHighlight highlight)
{
    FfxUInt32x2 position =
        FfxUInt32x2(clamp(floor(highlight.position * FFX_DOF_HIGHLIGHT_POSITION_STEPS + FfxFloat32x2(0.5f, 0.5f)),
                          FfxFloat32x2(0.0f, 0.0f), FfxFloat32x2(63.0f, 63.0f)));
    FfxUInt32 radius = FfxUInt32(clamp(floor(highlight.radius * FFX_DOF_HIGHLIGHT_RADIUS_STEPS + 0.5f), 0.0f, 4095.0f));
    FfxUInt32 spread = FfxUInt32(clamp(floor(highlight.spread * FFX_DOF_HIGHLIGHT_SPREAD_STEPS + 0.5f), 0.0f, 255.0f));
    FfxUInt32 energy = ffxDofPackRgb9e5(highlight.energy * (1.0f / FFX_DOF_HIGHLIGHT_ENERGY_UNIT));
    // A light too faint for the format's smallest step still left the layers: keep the slot marked.
    if ((energy & 0x7ffffffu) == 0u)
        energy = energy | 1u;
    FfxInt32x2 axis =
        FfxInt32x2(clamp(floor(highlight.axis * FFX_DOF_HIGHLIGHT_POSITION_STEPS + FfxFloat32x2(0.5f, 0.5f)),
                         FfxFloat32x2(-127.0f, -127.0f), FfxFloat32x2(127.0f, 127.0f)));
    return FfxUInt32x3(energy, position.x | (position.y << 6u) | (radius << 12u) | (spread << 24u),
                       (FfxUInt32(axis.x) & 0xffu) | ((FfxUInt32(axis.y) & 0xffu) << 8u) |
                           (highlight.near ? FFX_DOF_HIGHLIGHT_NEAR_BIT : 0u));
}
FFX_DOF_INLINE FfxDofHighlight ffxDofUnpackHighlight(FfxUInt32x3 words)
{
    FfxDofHighlight highlight;
    highlight.energy = ffxDofUnpackRgb9e5(words.x) * FFX_DOF_HIGHLIGHT_ENERGY_UNIT;
    highlight.position = FfxFloat32x2(FfxFloat32(words.y & 0x3fu), FfxFloat32((words.y >> 6u) & 0x3fu)) *
                         (1.0f / FFX_DOF_HIGHLIGHT_POSITION_STEPS);
    highlight.radius = FfxFloat32((words.y >> 12u) & 0xfffu) * (1.0f / FFX_DOF_HIGHLIGHT_RADIUS_STEPS);
    highlight.spread = FfxFloat32(words.y >> 24u) * (1.0f / FFX_DOF_HIGHLIGHT_SPREAD_STEPS);
    // Sign-extended from each byte.
    FfxInt32x2 axis = FfxInt32x2(FfxInt32(words.z << 24u) >> 24, FfxInt32((words.z << 16u) & 0xff000000u) >> 24);
    highlight.axis = FfxFloat32x2(axis) * (1.0f / FFX_DOF_HIGHLIGHT_POSITION_STEPS);
    highlight.near = (words.z & FFX_DOF_HIGHLIGHT_NEAR_BIT) != 0u;
    return highlight;
}

// The first word of slot `slot` of `tile` in HIGHLIGHTS.
FFX_DOF_INLINE FfxUInt32 ffxDofHighlightWord(FfxUInt32x2 tile, FfxUInt32 slot, FfxUInt32x2 tileCount)
{
    return (tile.y * tileCount.x + tile.x) * FfxUInt32(FFX_DOF_HIGHLIGHT_TILE_WORDS) +
           slot * FfxUInt32(FFX_DOF_HIGHLIGHT_WORDS);
}

// The word of `tile`'s floors in HIGHLIGHTS (ffxDofPackHighlightFloors).
FFX_DOF_INLINE FfxUInt32 ffxDofHighlightFloorWord(FfxUInt32x2 tile, FfxUInt32x2 tileCount)
{
    return (tile.y * tileCount.x + tile.x) * FfxUInt32(FFX_DOF_HIGHLIGHT_TILE_WORDS) +
           FfxUInt32(FFX_DOF_HIGHLIGHT_FLOOR_WORD);
}

// The word of `tile`'s colour peak in HIGHLIGHTS (pass 2: the largest finite channel of its pixels, ffxDofColorPeak),
// as float bits, clamped to the half range as TILES held it.
FFX_DOF_INLINE FfxUInt32 ffxDofHighlightPeakWord(FfxUInt32x2 tile, FfxUInt32x2 tileCount)
{
    return (tile.y * tileCount.x + tile.x) * FfxUInt32(FFX_DOF_HIGHLIGHT_TILE_WORDS) +
           FfxUInt32(FFX_DOF_HIGHLIGHT_PEAK_WORD);
}
FFX_DOF_INLINE FfxUInt32 ffxDofPackTilePeak(FfxFloat32 peak) { return ffxDofAsUInt(min(peak, FFX_DOF_FLOAT16_MAX)); }
FFX_DOF_INLINE FfxFloat32 ffxDofUnpackTilePeak(FfxUInt32 word) { return ffxDofAsFloat(word); }

// ---- Where they are drawn ---------------------------------------------------------------------------

// Whether a tile of (min, max) signed radius and colour peak `rangeAndPeak` (ffxDofTileRangeAndPeak) may hold
// highlights: a channel above white and far pixels of radius from FFX_DOF_HIGHLIGHT_MIN_RADIUS or near ones from
// FFX_DOF_NEAR_HIGHLIGHT_MIN_RADIUS (conservative: dilate lists the tiles such a tile's discs reach for the
// composite's full-resolution work).
FFX_DOF_INLINE FfxBoolean ffxDofTileMayHoldHighlights(FfxFloat32x3 rangeAndPeak)
{
    return rangeAndPeak.z > FFX_DOF_HIGHLIGHT_MIN_LUMINANCE &&
           (rangeAndPeak.x < -FFX_DOF_HIGHLIGHT_MIN_RADIUS || rangeAndPeak.y > FFX_DOF_NEAR_HIGHLIGHT_MIN_RADIUS);
}

#if defined(FFX_CPU)
FfxUInt32 ffxDofLoadHighlightWord(FfxUInt32 word);
#endif
// Only where the pass reads HIGHLIGHTS: a GLSL or HLSL function may not call an accessor its pass lacks.
#if defined(FFX_CPU) || FFX_DOF_USES_HIGHLIGHTS
// The word of floors of `tile` (of range and peak `rangeAndPeak`) where its pixels gave light to the highlights, else
// ffxDofNoHighlightFloors(): its colour peak first, which spares most tiles the load.
FFX_DOF_INLINE FfxUInt32 ffxDofLoadGivenHighlightFloors(FfxUInt32x2 tile, FfxFloat32x3 rangeAndPeak,
                                                        FfxUInt32x2 tileCount)
{
    if (!ffxDofTileMayHoldHighlights(rangeAndPeak))
        return ffxDofNoHighlightFloors();
    FfxUInt32 word = ffxDofLoadHighlightWord(ffxDofHighlightFloorWord(tile, tileCount));
    return ffxDofHighlightFloorsGaveLight(word) ? word : ffxDofNoHighlightFloors();
}
#endif
#if defined(FFX_CPU)
FfxFloat32x2 ffxDofLoadTile(FfxUInt32x2 tile);
#endif
// Only where the pass reads TILES and HIGHLIGHTS (dilate, the composite).
#if defined(FFX_CPU) || (FFX_DOF_USES_HIGHLIGHTS && FFX_DOF_USES_TILES)
// x, y: `tile`'s (min, max) signed radius (pass 1, TILES); z: its colour peak (pass 2, HIGHLIGHTS).
FFX_DOF_INLINE FfxFloat32x3 ffxDofTileRangeAndPeak(FfxUInt32x2 tile, FfxUInt32x2 tileCount)
{
    FfxFloat32x2 range = ffxDofLoadTile(tile);
    return FfxFloat32x3(range.x, range.y,
                        ffxDofUnpackTilePeak(ffxDofLoadHighlightWord(ffxDofHighlightPeakWord(tile, tileCount))));
}
#endif

// Tiles of the composite's window whose highlights it draws, a bit each in group-shared memory: up to 32 words,
// a window of 1024 tiles (ffxDofHighlightTileRange up to 15: radii up to 118 half-res px; farther highlights
// are not drawn).
#define FFX_DOF_HIGHLIGHT_WINDOW_WORDS 32
#define FFX_DOF_HIGHLIGHT_MAX_TILE_RANGE 15
#if (2 * FFX_DOF_HIGHLIGHT_MAX_TILE_RANGE + 1) * (2 * FFX_DOF_HIGHLIGHT_MAX_TILE_RANGE + 1) > \
    32 * FFX_DOF_HIGHLIGHT_WINDOW_WORDS
#error "the composite's window of highlight tiles must fit its bit mask"
#endif

// How far from a pixel a highlight of |radius| `radius` (half-res px) may add to it (full-res px): its disc
// stretched by the aperture and half its widest rim.
FFX_DOF_INLINE FfxFloat32 ffxDofHighlightReach(FfxFloat32 radius, FfxFloat32 extent)
{
    return 2.0f * radius * extent + 0.5f * FFX_DOF_HIGHLIGHT_MAX_RIM_WIDTH;
}

// Tiles each way within which a highlight's disc may reach a pixel of the central tile (tiles of 2
// FFX_DOF_TILE_SIZE full-res px), for the largest radius (cocLimit, half-res px) and the aperture's `extent`
// (ffxDofApertureExtent); at most FFX_DOF_HIGHLIGHT_MAX_TILE_RANGE.
FFX_DOF_INLINE FfxInt32 ffxDofHighlightTileRange(FfxFloat32 cocLimit, FfxFloat32 extent)
{
    return min(FfxInt32(ceil(ffxDofHighlightReach(cocLimit, extent) / (2.0f * FfxFloat32(FFX_DOF_TILE_SIZE)))),
               FfxInt32(FFX_DOF_HIGHLIGHT_MAX_TILE_RANGE));
}

// What a highlight adds to a pixel whose centre lies at `offset` from it (full-res px, pixel minus light): its
// energy spread over its disc of the aperture's shape, `radius` |CoC| in half-res px, over the disc's area (the
// shape's: its circle's over areaScale).
FFX_DOF_INLINE FfxFloat32x3 ffxDofHighlightAt(FfxDofHighlight highlight, FfxFloat32x2 offset,
                                              FfxDofPixelAperture aperture)
{
    FfxFloat32 radius = 2.0f * highlight.radius;
    // The gauge takes the offset from the pixel to the sample: the light lies at -offset. A near light's disc is
    // the shape turned over, as the blur draws near samples.
    FfxFloat32 gauge = ffxDofApertureDistance(aperture, -offset, highlight.near);
    // A light of a few pixels draws the union of its pixels' discs: a rim as wide as the light (a disc of
    // radius a has a root mean square spread of a / sqrt(2)), at least the one pixel of anti-aliasing.
    FfxFloat32 rimWidth = clamp(2.0f * FFX_DOF_SQRT2 * highlight.spread, 1.0f, FFX_DOF_HIGHLIGHT_MAX_RIM_WIDTH);
    FfxFloat32 reach = ffxDofSaturate((radius - gauge) / rimWidth + 0.5f);
    // A rim ramping linearly over w about r covers pi (r^2 + w^2 / 12); a rim wider than the disc (w > 2 r: a cone
    // from r + w / 2 to its top at the centre, r / w + 1/2) covers pi (r + w / 2)^3 / (3 w).
    FfxFloat32 outer = radius + 0.5f * rimWidth;
    FfxFloat32 area = rimWidth > 2.0f * radius ? FFX_DOF_PI * outer * outer * outer / (3.0f * rimWidth)
                                               : FFX_DOF_PI * (radius * radius + rimWidth * rimWidth * (1.0f / 12.0f));
    return highlight.energy * (reach * aperture.areaScale / area);
}

// What may hide a highlight from a pixel whose own far surface lies in front of the light. A point light is
// seen through the whole lens; a surface of radius c in front of it (|c| < the light's r) blocks the rays
// that reach pixel p where it covers the point light + (p - light) (1 - |c| / r) of the pinhole image
// (the rays from p to the light cross the surface's depth there). So a small surface beside a light hides
// none of its disc, and a large one in front of it cuts the disc where the thin lens cuts it. Returns
// whether the pixel's own surface lies in front (else nothing the pixel sees hides the light: a surface
// nearer than the pixel's own in front of the light would, which the pinhole image does not show there),
// and in `blocker` the point to look at (full-res px; `pixelCoc` and `highlightRadius` in half-res px).
FFX_DOF_INLINE FfxBoolean ffxDofHighlightBlockerPoint(FfxFloat32x2 pixelCentre, FfxFloat32x2 lightCentre,
                                                      FfxFloat32 pixelCoc, FfxFloat32 highlightRadius,
                                                      FFX_DOF_OUT(FfxFloat32x2) blocker)
{
    FfxFloat32 along = 1.0f + pixelCoc / max(highlightRadius, 1e-6f);
    blocker = lightCentre + (pixelCentre - lightCentre) * along;
    return pixelCoc <= -FFX_DOF_IN_FOCUS_RADIUS && -pixelCoc < highlightRadius - 0.5f;
}

// How much of a highlight of |radius| `highlightRadius` the surface of signed radius `blockerCoc` at the
// blocker point lets through (half-res px): all where it lies as far as the light, none where it lies a pixel
// or more nearer, in focus or near.
FFX_DOF_INLINE FfxFloat32 ffxDofHighlightVisibility(FfxFloat32 blockerCoc, FfxFloat32 highlightRadius)
{
    if (blockerCoc > -FFX_DOF_IN_FOCUS_RADIUS)
        return 0.0f;
    return ffxDofSaturate(-blockerCoc - highlightRadius + 1.5f);
}

// ---- What lies between a pixel and a light ------------------------------------------------------------
// A pixel whose own surface lies behind a light (a sky, a far wall) still loses the light to a far surface
// between them: the thin lens's rays from the pixel to the light cross each depth c in front of it at the point
// ffxDofHighlightBlockerPoint gives for c, all on the segment from the pixel to the light (c from 0 at the pixel
// to the light's radius at the light). The composite walks that segment (ffxDofHighlightVisibilityPast): each far
// surface it meets in front of the light is a depth to try, and the light is hidden where the surface at that
// depth's crossing point lies at that depth. So a branch in front of a light casts its band across the light's
// whole disc, as in the thin lens.
//
// The walk reads the input depth's radius at full resolution, a point per step, where HALF_COC would do with a
// quarter of the reads: a half-res texel holds one radius for its four pixels (the colour downsample's weighted
// mean), and where a small surface shares a texel with another it may take the other's: the walk on HALF_COC missed
// a row of a light 2 px high that way (tests/shaders, "A small light in front of a bright one casts its shadow").
// Its spacing along the segment's longer axis (half-res px): one texel, two pixels, so that it meets every blocker
// two pixels wide or more at every pixel whose rays cross it; a blocker of one pixel is met at about half of them.
#define FFX_DOF_HIGHLIGHT_WALK_SPACING 1.0f
// ... and its most steps, which holds that spacing up to a segment of 16 half-res px along its longer axis.
#define FFX_DOF_HIGHLIGHT_WALK_MAX_STEPS 16u
// How near (half-res px) the surface at a crossing point must lie to the depth tried to be the one crossed: the
// walk and the test read the same full-res radii, so a flat blocker meets its own depth exactly.
#define FFX_DOF_HIGHLIGHT_CROSSING_TOLERANCE 0.5f

// The steps of the walk from a light to a pixel `offset` full-res px from it.
FFX_DOF_INLINE FfxUInt32 ffxDofHighlightWalkSteps(FfxFloat32x2 offset)
{
    FfxFloat32 longer = 0.5f * max(abs(offset.x), abs(offset.y));
    return min(FfxUInt32(ceil(longer / FFX_DOF_HIGHLIGHT_WALK_SPACING)), FFX_DOF_HIGHLIGHT_WALK_MAX_STEPS);
}

// Whether a surface of signed radius `surfaceCoc` met on the walk is a depth to try: far, and in front of the light
// by the depth from which ffxDofHighlightVisibility hides all of it (the light's own rim and a background at the
// light's depth are not).
FFX_DOF_INLINE FfxBoolean ffxDofHighlightMayCross(FfxFloat32 surfaceCoc, FfxFloat32 highlightRadius)
{
    return surfaceCoc <= -FFX_DOF_IN_FOCUS_RADIUS && -surfaceCoc <= highlightRadius - 1.5f;
}

// Whether the surface of signed radius `crossedCoc` at the crossing point of the depth `triedCoc` is the one tried.
FFX_DOF_INLINE FfxBoolean ffxDofHighlightCrossed(FfxFloat32 crossedCoc, FfxFloat32 triedCoc)
{
    return abs(crossedCoc - triedCoc) <= FFX_DOF_HIGHLIGHT_CROSSING_TOLERANCE;
}

#endif  // FFX_DOF_HIGHLIGHTS_H
