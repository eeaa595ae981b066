// The aperture: the one place that knows the shape of a bokeh disc (issue 18). Unit-tested on the CPU
// (tests/shaders/ffx_dof_aperture_tests.cpp); the host computes the per-dispatch constants with the
// same functions (sdk/src/ffx_dof_plan.cpp).
//
// The unit shape S lives in aperture space u (x right, y up, radius 1 = the CoC radius):
//   - the unit circle, |u| <= 1;
//   - with N >= 3 blades, also every side n_k . u <= a of a regular N-gon, n_k at the blade rotation
//     plus 2 pi k / N, a the blades' inradius: the polygon inscribed in the circle (a = cos(pi / N),
//     roundness 0) up to the circle itself (a = 1); between them the corners are arcs of the circle;
//   - with cat's eye (optical vignetting), also |u - o| <= 1: a second disc whose centre o grows
//     toward the frame's edge (o = catEye * position, the position relative to the frame's centre,
//     y up, 1 at a corner), so discs become lens-shaped toward the corners.
// On screen, a far-field point (behind the focus plane) spreads over S with u.x divided by the
// anamorphic ratio (above 1: taller than wide); a near-field point over the same shape turned 180
// degrees, as through a thin lens (the reference renderer samples exactly this aperture).
//
// Every shape is convex and contains the origin, so it is the unit ball of its gauge
// ffxDofApertureDistance: a sample of radius r reaches a pixel whose offset has gauge g < r. The
// gauge of the intersection is the largest of the parts' gauges, each homogeneous of degree 1, so it
// is measured in any unit the offset is in (half-res px, MIP texels).
//
// The gauge runs once per blur sample, so it is straight-line code: a loop over the sides and one of
// zero or one pass for the cat's eye made six blades' blur and composite 1.3 times the circle's on
// lavapipe (any loop inside the sample loop costs there, whatever its count), the same code without
// loops 1.16 (docs/performance.md, "A gauge without loops"). The blades' gauge is the largest
// n_k . u / inradius over the sides; a regular polygon is symmetric about the line along its first
// side's normal n_0, and for even N also about the line across it, so u folded onto the positive side
// of those lines meets its largest value among the sides whose normals lie there: k = 0 .. (N - 1) / 2
// for odd N, k = 0 .. N / 4 for even N; at most FFX_DOF_FOLDED_BLADE_SIDES (15 blades), the slots past
// N's zero (a zero normal never raises the gauge, which is at least |u|). Most lenses need fewer: the
// blur's permutation FFX_DOF_APERTURE_SHAPES_COMPACT, which the core runs for a dispatch whose aperture
// has no cat's eye and folds to at most FFX_DOF_COMPACT_BLADE_SIDES sides (none, 3, 4 or 6 blades),
// compares that many and leaves the cat's-eye disc out: six blades' blur and composite 1.10 times the
// circle's instead of 1.17 (docs/performance.md, "A compact gauge per dispatch").
#ifndef FFX_DOF_APERTURE_H
#define FFX_DOF_APERTURE_H

#include "ffx_dof_portability.h"
#include "ffx_dof_constants.h"

#define FFX_DOF_PI 3.14159265359f
// The cat's-eye disc's centre is kept this far inside the circle's rim: at the rim the gauge of the
// clipping disc divides by 0.
#define FFX_DOF_CAT_EYE_MIN_SLACK 0.001f
// Sides of the folded polygon the gauge compares (the most, (15 - 1) / 2 + 1, is for 15 blades).
#define FFX_DOF_FOLDED_BLADE_SIDES 8
// The values of FFX_DOF_OPTION_APERTURE_SHAPES (ffx_dof_common.h) past 0, the circle's code alone:
#define FFX_DOF_APERTURE_SHAPES_ANY 1      // every aperture
#define FFX_DOF_APERTURE_SHAPES_COMPACT 2  // apertures whose gauge is compact (ffxDofApertureGaugeIsCompact)
// Folded sides the compact gauge compares.
#define FFX_DOF_COMPACT_BLADE_SIDES 2

// What this permutation's gauge compares: folded sides, and whether the cat's-eye disc.
#define FFX_DOF_GAUGE_SIDES FFX_DOF_FOLDED_BLADE_SIDES
#define FFX_DOF_GAUGE_CAT_EYE 1
#if defined(FFX_DOF_OPTION_APERTURE_SHAPES)
#if FFX_DOF_OPTION_APERTURE_SHAPES == FFX_DOF_APERTURE_SHAPES_COMPACT
#undef FFX_DOF_GAUGE_SIDES
#undef FFX_DOF_GAUGE_CAT_EYE
#define FFX_DOF_GAUGE_SIDES FFX_DOF_COMPACT_BLADE_SIDES
#define FFX_DOF_GAUGE_CAT_EYE 0
#endif
#endif

// ---- Areas (host and shader) ------------------------------------------------------------------------

// Inradius of the blades for a roundness (0: straight blades, 1: the circle).
FFX_DOF_INLINE FfxFloat32 ffxDofBladeInradius(FfxUInt32 blades, FfxFloat32 roundness)
{
    FfxFloat32 polygon = cos(FFX_DOF_PI / FfxFloat32(max(blades, 3u)));
    return polygon + (1.0f - polygon) * clamp(roundness, 0.0f, 1.0f);
}

// Area of the unit circle less the N segments the sides at `inradius` cut off (they do not overlap
// while inradius >= cos(pi / N)): pi for no blades.
FFX_DOF_INLINE FfxFloat32 ffxDofBladeShapeArea(FfxUInt32 blades, FfxFloat32 inradius)
{
    if (blades < 3u)
        return FFX_DOF_PI;
    FfxFloat32 a = clamp(inradius, 0.0f, 1.0f);
    FfxFloat32 segment = acos(a) - a * sqrt(max(1.0f - a * a, 0.0f));
    return FFX_DOF_PI - FfxFloat32(blades) * segment;
}

// Area of the intersection of two unit discs whose centres are `d` apart (0 <= d <= 2).
FFX_DOF_INLINE FfxFloat32 ffxDofUnitLensArea(FfxFloat32 d)
{
    FfxFloat32 h = clamp(d, 0.0f, 2.0f) * 0.5f;
    return 2.0f * (acos(h) - h * sqrt(max(1.0f - h * h, 0.0f)));
}

// Sides of an N-bladed polygon folded onto its symmetry lines (ffxDofApertureDistance): 0 for no blades.
FFX_DOF_INLINE FfxUInt32 ffxDofFoldedBladeSideCount(FfxUInt32 blades)
{
    if (blades == 0u)
        return 0u;
    return (blades & 1u) == 0u ? blades / 4u + 1u : (blades - 1u) / 2u + 1u;
}

// Whether FFX_DOF_APERTURE_SHAPES_COMPACT draws an aperture of these constants (bladeCount, catEye).
FFX_DOF_INLINE FfxBoolean ffxDofApertureGaugeIsCompact(FfxUInt32 blades, FfxFloat32 catEye)
{
    return catEye == 0.0f && ffxDofFoldedBladeSideCount(blades) <= FFX_DOF_COMPACT_BLADE_SIDES;
}

// ---- The per-pixel aperture -------------------------------------------------------------------------

struct FfxDofPixelAperture
{
    FfxFloat32 anamorphicRatio;  // u.x = screen x * ratio
    FfxFloat32x2 bladeNormal;    // the first side's normal over the inradius
    FfxFloat32x2 bladeStep;      // (cos, sin) of the angle between neighbouring sides
    FfxFloat32x2 bladeAxis;      // n_0, the first side's unit normal: the line u is folded about
    FfxFloat32 bladeFoldAcross;  // -1 for even N (folded across the line too: x = |n_0 . u|), else 1
    // n_k / inradius in n_0's frame, k = 0 .. the folded sides of N (ffxDofApertureDistance); zero past them.
    FfxFloat32x2 bladeFoldedSides[FFX_DOF_GAUGE_SIDES];
    FfxFloat32x2 clipCenter;  // the cat's-eye disc's centre
    FfxFloat32 clipSlack;     // 1 - |clipCenter|^2
    FfxFloat32 inverseClipSlack;
    FfxFloat32 areaScale;        // pi / the pixel-space area of the shape of radius 1
    FfxFloat32 inscribedRadius;  // of the largest circle |u| < r inside the shape: 1 for round discs
};

// The round aperture's values (what the circle's path carries, never reading them).
FFX_DOF_INLINE FfxDofPixelAperture ffxDofRoundAperture()
{
    FfxDofPixelAperture aperture;
    aperture.anamorphicRatio = 1.0f;
    aperture.bladeNormal = FfxFloat32x2(0.0f, 0.0f);
    aperture.bladeStep = FfxFloat32x2(1.0f, 0.0f);
    aperture.bladeAxis = FfxFloat32x2(1.0f, 0.0f);
    aperture.bladeFoldAcross = 1.0f;
    FFX_DOF_UNROLL
    for (FfxInt32 side = 0; side < FFX_DOF_GAUGE_SIDES; ++side)
        aperture.bladeFoldedSides[side] = FfxFloat32x2(0.0f, 0.0f);
    aperture.clipCenter = FfxFloat32x2(0.0f, 0.0f);
    aperture.clipSlack = 1.0f;
    aperture.inverseClipSlack = 1.0f;
    aperture.areaScale = 1.0f;
    aperture.inscribedRadius = 1.0f;
    return aperture;
}

// Position of a pixel relative to the frame's centre, y up, 1 at a corner (the cat's eye's measure).
FFX_DOF_INLINE FfxFloat32x2 ffxDofFramePosition(FfxFloat32x2 pixel, FfxFloat32x2 frameSize)
{
    FfxFloat32 halfDiagonal = 0.5f * sqrt(dot(frameSize, frameSize));
    return FfxFloat32x2(pixel.x - 0.5f * frameSize.x, 0.5f * frameSize.y - pixel.y) / halfDiagonal;
}

// The next side's normal: `normal` turned counter-clockwise by the angle whose (cos, sin) is `step`.
FFX_DOF_INLINE FfxFloat32x2 ffxDofNextBladeSide(FfxFloat32x2 normal, FfxFloat32x2 step)
{
    return FfxFloat32x2(normal.x * step.x - normal.y * step.y, normal.x * step.y + normal.y * step.x);
}

// Rows the area of a bladed cat's eye is integrated over (ffxDofBladedCatEyeArea): 0.1% at most.
#define FFX_DOF_CAT_EYE_AREA_ROWS 48u

// Area of the shape of `blades` blades clipped by the cat's-eye disc, integrated over rows (each row of
// a convex shape is one interval: the circle's, the disc's and every side's bounds intersected). No
// closed form: the blades cut the disc's rim anywhere. Costs what a few dozen samples cost, once per
// texel, and only where blades and cat's eye meet.
FFX_DOF_INLINE FfxFloat32 ffxDofBladedCatEyeArea(FfxDofPixelAperture aperture, FfxUInt32 blades, FfxUInt32 rows)
{
    FfxFloat32 area = 0.0f;
    FfxFloat32 rowHeight = 2.0f / FfxFloat32(max(rows, 1u));
    FFX_DOF_LOOP
    for (FfxUInt32 row = 0u; row < rows; ++row)
    {
        FfxFloat32 y = (FfxFloat32(row) + 0.5f) * rowHeight - 1.0f;
        FfxFloat32 circleHalf = sqrt(max(1.0f - y * y, 0.0f));
        FfxFloat32 clipY = y - aperture.clipCenter.y;
        FfxFloat32 clipHalf = sqrt(max(1.0f - clipY * clipY, 0.0f));
        FfxFloat32 first = max(-circleHalf, aperture.clipCenter.x - clipHalf);
        FfxFloat32 last = clipY * clipY < 1.0f ? min(circleHalf, aperture.clipCenter.x + clipHalf) : first;
        FfxFloat32x2 normal = aperture.bladeNormal;
        FFX_DOF_LOOP
        for (FfxUInt32 side = 0u; side < blades; ++side)
        {
            // normal . (x, y) <= 1, bounding x from the side the normal points to.
            FfxFloat32 bound = 1.0f - normal.y * y;
            if (abs(normal.x) < 1e-6f)
                last = bound < 0.0f ? first : last;
            else if (normal.x > 0.0f)
                last = min(last, bound / normal.x);
            else
                first = max(first, bound / normal.x);
            normal = ffxDofNextBladeSide(normal, aperture.bladeStep);
        }
        area += max(last - first, 0.0f) * rowHeight;
    }
    return area;
}

// The aperture seen by the pixel at `pixel` (half-res px) of a frame of `frameSize` half-res px.
FFX_DOF_INLINE FfxDofPixelAperture ffxDofMakeAperture(FfxDofConstants constants, FfxFloat32x2 pixel,
                                                      FfxFloat32x2 frameSize)
{
    FfxDofPixelAperture aperture;
    aperture.anamorphicRatio = constants.anamorphicRatio;
    aperture.bladeNormal = constants.bladeNormal;
    FfxUInt32 blades = constants.bladeCount;
    FfxFloat32 stepAngle = 2.0f * FFX_DOF_PI / FfxFloat32(max(blades, 1u));
    aperture.bladeStep = FfxFloat32x2(cos(stepAngle), sin(stepAngle));
    FfxBoolean even = (blades & 1u) == 0u;
    FfxFloat32 inverseInradius = length(constants.bladeNormal);
    aperture.bladeAxis = blades != 0u ? constants.bladeNormal / inverseInradius : FfxFloat32x2(1.0f, 0.0f);
    aperture.bladeFoldAcross = even ? -1.0f : 1.0f;
    FfxUInt32 foldedSides = ffxDofFoldedBladeSideCount(blades);
    FfxFloat32x2 sideNormal = FfxFloat32x2(inverseInradius, 0.0f);
    FFX_DOF_UNROLL
    for (FfxInt32 side = 0; side < FFX_DOF_GAUGE_SIDES; ++side)
    {
        aperture.bladeFoldedSides[side] = FfxUInt32(side) < foldedSides ? sideNormal : FfxFloat32x2(0.0f, 0.0f);
        sideNormal = ffxDofNextBladeSide(sideNormal, aperture.bladeStep);
    }
    aperture.clipCenter = constants.catEye * ffxDofFramePosition(pixel, frameSize);
    FfxFloat32 offset2 = dot(aperture.clipCenter, aperture.clipCenter);
    aperture.clipSlack = max(1.0f - offset2, FFX_DOF_CAT_EYE_MIN_SLACK);
    aperture.inverseClipSlack = 1.0f / aperture.clipSlack;
    FfxBoolean catEye = constants.catEye > 0.0f;
    aperture.areaScale = constants.apertureAreaScale;
    FfxFloat32 bladeInradius = blades != 0u ? 1.0f / inverseInradius : 1.0f;
    FfxFloat32 clipInradius = catEye ? 1.0f - sqrt(offset2) : 1.0f;
    aperture.inscribedRadius = min(bladeInradius, clipInradius);
    // The cat's eye changes the area per pixel: exactly for round discs (two discs' lens), by rows
    // with blades.
    if (catEye && blades == 0u)
        aperture.areaScale *= FFX_DOF_PI / ffxDofUnitLensArea(sqrt(offset2));
    FfxUInt32 areaRows = catEye && blades != 0u ? FFX_DOF_CAT_EYE_AREA_ROWS : 0u;
    FfxFloat32 bladedArea = ffxDofBladedCatEyeArea(aperture, blades, areaRows);
    if (areaRows != 0u)
        aperture.areaScale = FFX_DOF_PI * constants.anamorphicRatio / max(bladedArea, 1e-3f);
    return aperture;
}

// Gauge of the offset from a pixel to a sample (y down, any unit): the radius a sample needs to
// reach the pixel. `nearSample`: the sample is in the near field, whose disc is the shape turned 180
// degrees. For the round aperture, the offset's length. Blades and cat's eye that are off give |u|
// (zero side normals; a clipping disc at the centre): no branch, no loop (see the top of this file).
FFX_DOF_INLINE FfxFloat32 ffxDofApertureDistance(FfxDofPixelAperture aperture, FfxFloat32x2 sampleOffset,
                                                 FfxBoolean nearSample)
{
    // A far sample at offset d reaches the pixel at -d: u is -d, y flipped up, x stretched.
    FfxFloat32 side = nearSample ? 1.0f : -1.0f;
    FfxFloat32x2 u = FfxFloat32x2(sampleOffset.x * (side * aperture.anamorphicRatio), sampleOffset.y * -side);
    FfxFloat32 length2 = dot(u, u);
    FfxFloat32 gauge = sqrt(length2);
    FfxFloat32 alongAxis = dot(aperture.bladeAxis, u);
    FfxFloat32x2 folded = FfxFloat32x2(max(alongAxis, alongAxis * aperture.bladeFoldAcross),
                                       abs(aperture.bladeAxis.x * u.y - aperture.bladeAxis.y * u.x));
    FFX_DOF_UNROLL
    for (FfxInt32 side = 0; side < FFX_DOF_GAUGE_SIDES; ++side)
        gauge = max(gauge, dot(aperture.bladeFoldedSides[side], folded));
#if FFX_DOF_GAUGE_CAT_EYE
    // The cat's eye: the t with |u / t - c| = 1, the smaller root of a quadratic, written without
    // cancellation.
    FfxFloat32 along = dot(u, aperture.clipCenter);
    gauge = max(gauge, (sqrt(along * along + length2 * aperture.clipSlack) - along) * aperture.inverseClipSlack);
#endif
    return gauge;
}

// A sample spreads its energy over its disc: weight proportional to the inverse disc area, normalized
// so that a round disc of radius r weighs 1 / r^2 (at most 4: radii below half a pixel weigh as half
// a pixel), and every shape's disc sums to pi like the circle's.
FFX_DOF_INLINE FfxFloat32 ffxDofApertureAreaWeight(FfxDofPixelAperture aperture, FfxFloat32 absRadius)
{
    return aperture.areaScale / max(absRadius * absRadius, 0.25f);
}
// The same for the round aperture (areaScale 1), as the circle's path computes it.
FFX_DOF_INLINE FfxFloat32 ffxDofRoundAreaWeight(FfxFloat32 absRadius)
{
    return 1.0f / max(absRadius * absRadius, 0.25f);
}

// ---- The shape's extent, for the kernel walk and the tile passes -------------------------------------

// The walk reads the ellipse |u| < radius that holds every shape: half the width of its row `dy` from
// the centre (same units), `widthScale` the inverse anamorphic ratio (1 for round discs). A convex
// polygon's rows are one interval too, but the round row keeps the walk's cost at one square root and
// reads at most the corners a polygon leaves out (docs/aperture.md).
FFX_DOF_INLINE FfxFloat32 ffxDofKernelRowHalfWidth(FfxFloat32 radius, FfxFloat32 dy, FfxFloat32 widthScale)
{
    return sqrt(max(radius * radius - dy * dy, 0.0f)) * widthScale;
}

// The largest distance, over the radius, at which a disc reaches: the tile passes multiply radii by it.
FFX_DOF_INLINE FfxFloat32 ffxDofApertureExtent(FfxDofConstants constants)
{
    return max(1.0f, 1.0f / constants.anamorphicRatio);
}

// The smallest pixel distance, over the radius, between rings: the MIP the blur reads is chosen by it,
// so that a disc narrowed by the anamorphic ratio is not read coarser than its width allows.
FFX_DOF_INLINE FfxFloat32 ffxDofApertureRingSpacingScale(FfxDofConstants constants)
{
    return min(1.0f, 1.0f / constants.anamorphicRatio);
}

#endif  // FFX_DOF_APERTURE_H
