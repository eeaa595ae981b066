// Lens and depth-buffer model of the ffx-dof command line: from camera parameters given in
// photographers' units to the effect's cocScale / cocBias and the depth values to upload.
//
// The effect wants radius = d * cocScale + cocBias for the depth value d it reads (in half-resolution
// pixels, positive in the near field). The thin-lens radius is affine in 1 / Z (Z = view distance), so
// d must be a perspective ("device z") depth. Three ways to get one are supported:
//
//  * linear depth (a renderer's Z pass, metres): the tool uploads d = n / Z with n = the smallest depth
//    of the image. That is exactly the device z of a reversed infinite perspective projection with its
//    near plane at n (clipZ = n, clipW = z), so every d lies in (0, 1] and FFX_DOF_REVERSE_DEPTH is set.
//  * device depth with --near / --far: a standard D3D-style (left-handed, z in [0, 1]) projection,
//    or its reversed form (near at 1, far at 0) with --reverse-depth; --far inf gives the infinite form.
//  * device depth with --proj: the 16 numbers of the engine's projection matrix, row-major, for column
//    vectors (clip = M * view); only rows 3 and 4 matter. Whether depth is reversed follows from it.
#pragma once

#include "ffx_dof.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ffxdof::cli {

// The f-number when neither --fstop nor --aperture-radius is given.
constexpr double kDefaultFNumber = 2.8;

// A thin lens as given on the command line.
struct LensSettings {
    double focusMetres = 0.0;                    // distance of the plane in focus, metres, > focal length
    double focalLengthMm = 50.0;                 // focal length, millimetres, > 0
    double sensorWidthMm = 36.0;                 // width of the sensor (image) plane, millimetres, > 0
    std::optional<double> fNumber;               // f-number N: aperture radius = focal length / (2 N); > 0
    std::optional<double> apertureRadiusMetres;  // or the aperture radius itself, metres, >= 0
};

// A thin lens in metres, validated.
struct ThinLens {
    double apertureRadius = 0.0;  // metres
    double focalLength = 0.0;     // metres
    double focusDistance = 0.0;   // metres
    double sensorWidth = 0.0;     // metres
    // The option the aperture radius came from, for messages: "--fstop" or "--aperture-radius".
    std::string apertureOption = "--aperture-radius";
};

// Checks every value and converts to metres; throws CliError(InvalidValue) naming the bad option.
// With neither fNumber nor apertureRadiusMetres it is a usage error (the parser supplies a default).
// With autofocus the focus is not given (focusMetres is ignored, focusDistance is 0): autofocus
// chooses it on the device.
ThinLens makeThinLens(const LensSettings& settings, bool autofocus = false);

// Half-resolution pixels per metre on the sensor of an image imageWidth pixels wide:
// 0.5 * imageWidth / sensorWidth (the SDK's `conversion`).
double halfResPixelsPerSensorMetre(const ThinLens& lens, uint32_t imageWidth);

// The thin-lens CoC radius of a point at view distance z, in half-resolution pixels of an image
// imageWidth pixels wide: |A f (F - z)| / (z (F - f)) * 0.5 * imageWidth / sensorWidth, signed
// positive in front of the focus plane. This is the truth the effect's affine form must reproduce.
double thinLensCocHalfResPixels(const ThinLens& lens, double z, uint32_t imageWidth);

// The terms of a perspective projection that relate view z to device depth:
// clipZ = m33 * z + m34, clipW = m43 * z, d = clipZ / clipW (1-based row, column).
struct DepthProjection {
    double m33 = 0.0;
    double m34 = 0.0;
    double m43 = 0.0;
    bool reversed = false;  // depth decreases with distance (FFX_DOF_REVERSE_DEPTH)

    // The device depth of a point at view distance `distance` (> 0) in front of the camera.
    double deviceDepth(double distance) const;
    // The inverse: the view distance of device depth d.
    double viewDistance(double deviceDepth) const;
};

// D3D-style projection between near and far (0 < near < far; far may be +infinity).
DepthProjection projectionFromNearFar(double nearPlane, double farPlane, bool reversed);

// From the 16 numbers of --proj (row-major, column vectors). Throws CliError(InvalidValue) when the
// matrix is not a perspective projection or when reversedRequested contradicts it.
DepthProjection projectionFromMatrix(const std::array<double, 16>& rowMajor, bool reversedRequested);

// The projection the tool uses for linear depth: reversed infinite with near plane at nearestDepth.
DepthProjection projectionForLinearDepth(double nearestDepth);

struct CocParameters {
    float cocScale = 0.0f;
    float cocBias = 0.0f;
};

// cocScale / cocBias for FfxDofDispatchDescription, through the SDK's ffxDofCalculateCocScale/Bias,
// which compute in single precision. Throws CliError(InvalidValue) naming the option responsible when
// a lens value or projection term does not fit a float (beyond 3.4e38, or non-zero below 1.2e-38), or
// naming every input when the result is still not finite. projectionOrigin says where the projection
// came from ("--near/--far", "--proj", "the nearest depth of d.exr (... at x=.., y=..)").
CocParameters computeCocParameters(const ThinLens& lens, const DepthProjection& projection, uint32_t imageWidth,
                                   const std::string& projectionOrigin = "the depth projection");

// The largest |d * cocScale + cocBias| over device depths (half-res px).
float largestCocRadius(const std::vector<float>& deviceDepth, const CocParameters& coc);

// ---- Autofocus: --autofocus X,Y [--focus-region R] instead of --focus (docs/cli.md, "Autofocus") ----

// The region's width and height when --focus-region is not given: a tenth of the image's.
constexpr double kDefaultFocusRegion = 0.1;
// The farthest focus where the depth has no far plane (linear depth, --far inf, an infinite --proj)
// or one beyond it: 10 km, infinity for every lens the tool models (focused there, a 300 mm f/2.8 lens
// on a 36 mm, 4096-pixel-wide sensor blurs infinity by under 0.1 half-res px).
constexpr double kAutofocusFarthest = 10000.0;

struct AutofocusRegion {
    double x = 0.5, y = 0.5;            // centre, normalized image coordinates, origin top-left
    double size = kDefaultFocusRegion;  // width and height as fractions of the image's width and height
};

// "X,Y": exactly two numbers (strtod's syntax) separated by one comma. Returns an empty string when
// the text is well formed, else why not (the parser reports it as a usage error naming --autofocus).
std::string autofocusPointSyntaxError(const std::string& text);
// Parses text that autofocusPointSyntaxError accepts (throws CliError(Usage) naming --autofocus otherwise).
AutofocusRegion parseAutofocusPoint(const std::string& text, double size = kDefaultFocusRegion);
// X and Y in [0, 1], the size in (0, 1]; throws CliError(InvalidValue) naming the option.
void checkAutofocusRegion(const AutofocusRegion& region);

// The distances autofocus may choose, metres.
struct FocusRange {
    double nearest = 0.0, farthest = 0.0;
};
// From twice the focal length (1:1 magnification, as close as a macro lens focuses; the SDK needs more
// than the focal length) to the projection's far plane, or kAutofocusFarthest where there is none or it
// lies beyond. Throws CliError(InvalidValue) when the far plane is not beyond twice the focal length.
FocusRange autofocusRange(const ThinLens& lens, const DepthProjection& projection);

// The dispatch's FfxDofAutofocus: the lens and projection terms exactly as computeCocParameters gives
// them to ffxDofCalculateCocScale / Bias, the region, the range; timeConstant 0 (every frame focuses on
// its own: no smoothing).
FfxDofAutofocus makeAutofocus(const ThinLens& lens, const DepthProjection& projection, uint32_t imageWidth,
                              const AutofocusRegion& region, const FocusRange& range);

// The focus distances autofocus can arrive at on this depth image (width x height device depths): it
// reads only pixels of the region and the 3x3 pixels at its centre and averages inverse distances of
// some of them, so its choice lies within their distance range, clamped to `range`. The tool sizes the
// CoC limit for the whole of it before the dispatch (the chosen distance comes back with the output).
FocusRange reachableAutofocus(const std::vector<float>& deviceDepth, uint32_t width, uint32_t height,
                              const DepthProjection& projection, const AutofocusRegion& region,
                              const FocusRange& range);

// "focus: 2.48 m": the distance with three significant digits (at least), in fixed notation.
std::string focusText(double metres);

}  // namespace ffxdof::cli
