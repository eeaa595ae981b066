/*
 * ffx-dof: a depth-of-field (bokeh) post-process for Vulkan and Direct3D 12,
 * an independent implementation of the technique of FidelityFX Depth of Field 1.1.
 *
 * This is the API-neutral host interface. It is valid C99 and C++. The names and the
 * meaning of every call and field follow FidelityFX DoF 1.1 so that an existing
 * integration ports by changing its backend set-up and resource wrapping only:
 * see ffx_dof_vk.h and ffx_dof_dx12.h for those.
 *
 * Version 2.1.0
 *   - Aperture shapes: FfxDofDispatchDescription::pAperture (blades, rotation, roundness, anamorphic
 *     ratio, cat's eye; docs/aperture.md). The dispatch description grew by one pointer: rebuild.
 * Version 2.0.0
 *   - Autofocus: FfxDofDispatchDescription::pAutofocus, ffxDofContextResetAutofocus,
 *     ffxDofContextGetAutofocusDistance (docs/autofocus.md).
 *   - Vulkan: FfxDofBackendDescriptionVK::pEnabledFeatures (the vkCreateDevice chain) replaces
 *     shaderFloat16Enabled / storage16BitEnabled / subgroupSizeControlEnabled; views of engine
 *     images are kept (ffxDofContextReleaseImageVK); FFX_DOF_VK_TIMESTAMP_COUNT is 7.
 * Version 1.0.0
 *   - First release: five compute passes, Vulkan backend, D3D12 backend, 16-bit and
 *     wave64 permutations, opaque heap-allocated context and backend handles.
 */
#ifndef FFX_DOF_H
#define FFX_DOF_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FFX_DOF_VERSION_MAJOR 2
#define FFX_DOF_VERSION_MINOR 1
#define FFX_DOF_VERSION_PATCH 0

/** Packs a version as FidelityFX does: major in bits 22..31, minor in 12..21, patch in 0..11. */
#define FFX_DOF_MAKE_VERSION(major, minor, patch) \
    ((uint32_t)(((uint32_t)(major) << 22) | ((uint32_t)(minor) << 12) | (uint32_t)(patch)))

/** Highest accepted FfxDofContextDescription::quality (number of kernel sample rings). */
#define FFX_DOF_MAX_QUALITY 32u

/** Accepted ranges of FfxDofAperture's fields. */
#define FFX_DOF_MAX_APERTURE_BLADES 16u
#define FFX_DOF_MIN_ANAMORPHIC_RATIO 0.5f
#define FFX_DOF_MAX_ANAMORPHIC_RATIO 2.0f

/** Largest accepted width or height of the input and output images, in pixels. */
#define FFX_DOF_MAX_RESOLUTION 16384u

typedef uint32_t FfxDofVersionNumber;

/** Every call returns one of these. FFX_DOF_OK is zero; every error is negative. */
typedef enum FfxDofErrorCode {
    FFX_DOF_OK = 0,
    FFX_DOF_ERROR_INVALID_POINTER = -1,      /**< a required pointer or handle is null */
    FFX_DOF_ERROR_INVALID_RESOLUTION = -2,   /**< width or height is 0 or above FFX_DOF_MAX_RESOLUTION */
    FFX_DOF_ERROR_INVALID_QUALITY = -3,      /**< quality is 0 or above FFX_DOF_MAX_QUALITY */
    FFX_DOF_ERROR_INVALID_COC_LIMIT = -4,    /**< cocLimitFactor is negative, NaN or infinite */
    FFX_DOF_ERROR_INVALID_FLAGS = -5,        /**< a flag bit that is not one of FfxDofInitializationFlagBits */
    FFX_DOF_ERROR_INVALID_RESOURCE = -6,     /**< a null image, an unsupported format or the wrong size */
    FFX_DOF_ERROR_OUTPUT_ALIASES_INPUT = -7, /**< output is the color image but FFX_DOF_OUTPUT_PRE_INIT is not set */
    FFX_DOF_ERROR_INVALID_CONTEXT = -8,      /**< the context was destroyed or never created */
    FFX_DOF_ERROR_INVALID_ARGUMENT = -9,     /**< another field is out of range (for example a non-finite cocScale) */
    FFX_DOF_ERROR_UNSUPPORTED = -10,   /**< the device lacks a required feature, or no shader binaries exist for it */
    FFX_DOF_ERROR_OUT_OF_MEMORY = -11, /**< a host or device allocation failed */
    FFX_DOF_ERROR_BACKEND = -12,       /**< the graphics API returned an error; see ffxDofGetLastErrorMessage */
    FFX_DOF_ERROR_BACKEND_IN_USE = -13 /**< the backend still has live contexts */
} FfxDofErrorCode;

/** Bits of FfxDofContextDescription::flags. */
typedef enum FfxDofInitializationFlagBits {
    /** The depth buffer is inverted (near plane at 1, far plane at 0). */
    FFX_DOF_REVERSE_DEPTH = (1 << 0),
    /** The output already holds the input color: only changed pixels are written, and output may be
     *  the color image itself (in-place). */
    FFX_DOF_OUTPUT_PRE_INIT = (1 << 1),
    /** Never gather inner kernel rings from higher MIP levels (slower; for reference comparisons). */
    FFX_DOF_DISABLE_RING_MERGE = (1 << 2),
    /** Dispatches may give a shaped FfxDofAperture (not in FidelityFX DoF 1.1). Without it the blur is the
     *  circle's code alone; a shader holding both paths made the round aperture's blur 11 to 27% slower
     *  (docs/aperture.md), so contexts that never shape their bokeh do not pay for it. */
    FFX_DOF_ENABLE_APERTURE_SHAPES = (1 << 3)
} FfxDofInitializationFlagBits;

#define FFX_DOF_ALL_FLAGS                                                                      \
    ((uint32_t)(FFX_DOF_REVERSE_DEPTH | FFX_DOF_OUTPUT_PRE_INIT | FFX_DOF_DISABLE_RING_MERGE | \
                FFX_DOF_ENABLE_APERTURE_SHAPES))

typedef struct FfxDofDimensions2D {
    uint32_t width;
    uint32_t height;
} FfxDofDimensions2D;

/** A graphics-API backend (Vulkan or D3D12) made by ffxDofBackendCreateVK or ffxDofBackendCreateDX12.
 *  It owns the pipelines and can serve many contexts; it must outlive every context made with it. */
typedef struct FfxDofBackend_T* FfxDofBackend;

/** An effect instance for one resolution and set of options; owns the internal images. */
typedef struct FfxDofContext_T* FfxDofContext;

/** The engine's command buffer (VkCommandBuffer) or command list (ID3D12GraphicsCommandList*).
 *  Wrap it with ffxDofGetCommandListVK or ffxDofGetCommandListDX12. */
typedef void* FfxDofCommandList;

/** An engine-owned image, described for one dispatch. Make it with ffxDofGetResourceVK or
 *  ffxDofGetResourceDX12; the fields are the API's own values. */
typedef struct FfxDofResource {
    uint64_t handle; /**< VkImage, or ID3D12Resource* cast to an integer; 0 is invalid */
    uint32_t format; /**< VkFormat or DXGI_FORMAT of the image (or of the view to use) */
    uint32_t width;  /**< in pixels; must equal FfxDofContextDescription::resolution */
    uint32_t height;
    uint32_t state; /**< VkImageLayout or D3D12_RESOURCE_STATES the image is in before the
                         dispatch; the effect leaves it in the same state */
    uint32_t flags; /**< backend-specific bits, see ffx_dof_vk.h / ffx_dof_dx12.h */
} FfxDofResource;

/** Parameters fixed for the lifetime of a context. Zero-initialise, then set every field. */
typedef struct FfxDofContextDescription {
    /** FfxDofInitializationFlagBits; unknown bits are an error. */
    uint32_t flags;
    /** Maximum number of kernel sample rings, 1..FFX_DOF_MAX_QUALITY. Samples per pixel grow with
     *  its square; the ring count actually used also shrinks with the radius. Typical: 10. */
    uint32_t quality;
    /** Width and height of color, depth and output, in pixels, 1..FFX_DOF_MAX_RESOLUTION. */
    FfxDofDimensions2D resolution;
    /** The backend to run on; not owned by the context. */
    FfxDofBackend backendInterface;
    /** Largest CoC radius as a fraction of resolution.height (0.01 = 1% of the image height).
     *  Larger radii are clamped, which bounds the cost. 0 clamps every radius to 0 (no blur).
     *  Must be finite and non-negative. Typical: 0.01 to 0.05. */
    float cocLimitFactor;
} FfxDofContextDescription;

/** Autofocus (not in FidelityFX DoF 1.1): the dispatch picks its focus distance from the depth in a
 *  region, on the GPU, instead of taking cocScale / cocBias. See docs/autofocus.md. Zero-initialise,
 *  then set every field. */
typedef struct FfxDofAutofocus {
    /** Centre of the region, normalized image coordinates (0,0 top-left, 1,1 bottom-right). */
    float regionCenter[2];
    /** Width and height of the region, normalized (0 < size <= 1; e.g. 0.1 = a tenth of the image). */
    float regionSize[2];
    /** The lens and projection, as ffxDofCalculateCocScale takes them: aperture radius, focal length
     *  (same unit as the distances), sensor units -> half-resolution pixels, and the projection terms. */
    float aperture;
    float focalLength;
    float conversion;
    float proj33, proj34, proj43;
    /** The focus distance is clamped to [minFocusDistance, maxFocusDistance] (positive, same unit;
     *  focalLength < minFocusDistance <= maxFocusDistance, finite). */
    float minFocusDistance;
    float maxFocusDistance;
    /** Seconds for the focus to cover 63% of a change (exponential, in dioptres); 0 = no smoothing. */
    float timeConstant;
    /** Seconds since the previous dispatch of this context. */
    float deltaTime;
} FfxDofAutofocus;

/** The shape of the aperture, and so of every bokeh disc (not in FidelityFX DoF 1.1, which renders
 *  circles). The conventions follow Blender's camera: see docs/aperture.md. All zero but
 *  anamorphicRatio = 1 is the circle, exactly as with pAperture = NULL. Zero-initialise, then set every
 *  field. */
typedef struct FfxDofAperture {
    /** Number of aperture blades: 0 = round, or 3..16 (a polygon). */
    uint32_t bladeCount;
    /** Rotation of the blades, radians, counter-clockwise on screen: 0 puts flat sides left and right
     *  (and, for an odd count, a flat side on the right). Any finite value. */
    float bladeRotation;
    /** 0 = straight blades (a regular polygon) .. 1 = a circle; between, the corners are rounded. */
    float roundness;
    /** Disc height over width, 0.5..2 (anamorphic lenses: 1.33 to 2). Above 1 the height stays the
     *  CoC diameter and the width narrows; below 1 the disc widens. 1 = round. */
    float anamorphicRatio;
    /** Optical vignetting, 0..1: toward the frame's edges discs are clipped by a second disc into cat's
     *  eyes (at 1, a frame corner keeps the lens-shaped intersection of two discs one radius apart).
     *  0 = off. */
    float catEye;
} FfxDofAperture;

/** Per-frame parameters. */
typedef struct FfxDofDispatchDescription {
    /** The engine's command buffer, recording; the effect appends to it and never submits it. */
    FfxDofCommandList commandList;
    /** Scene color, full resolution, sampled. */
    FfxDofResource color;
    /** Scene depth (device z), full resolution, sampled. Vulkan accepts VK_FORMAT_D32_SFLOAT,
     *  D24_UNORM_S8_UINT and D16_UNORM, read through a depth-aspect view, and R32_SFLOAT (a copy of
     *  depth in a colour image), read through a colour-aspect view. D3D12 accepts a depth buffer
     *  created typeless (D32_FLOAT, D24_UNORM_S8_UINT, D16_UNORM, D32_FLOAT_S8X24_UINT families,
     *  declared by any format of the family) and R32_FLOAT or R16_UNORM copies
     *  (docs/integration-d3d12.md). Anything else is FFX_DOF_ERROR_INVALID_RESOURCE. */
    FfxDofResource depth;
    /** Destination, full resolution, written as a storage image / UAV. May be the color image only
     *  with FFX_DOF_OUTPUT_PRE_INIT. */
    FfxDofResource output;
    /** CoC radius in half-resolution pixels = depth * cocScale + cocBias, signed: positive for the
     *  near field, negative for the far field. See ffxDofCalculateCocScale / ffxDofCalculateCocBias. */
    float cocScale;
    float cocBias;
    /** NULL: manual focus (cocScale / cocBias). Otherwise autofocus decides the focus on the GPU and
     *  cocScale / cocBias are ignored. Read during the call only. */
    const FfxDofAutofocus* pAutofocus;
    /** NULL: a round aperture. Otherwise the aperture's shape for this dispatch (it may change every
     *  frame at no cost); a shape other than the round one needs a context created with
     *  FFX_DOF_ENABLE_APERTURE_SHAPES (else FFX_DOF_ERROR_INVALID_ARGUMENT). Read during the call only. */
    const FfxDofAperture* pAperture;
} FfxDofDispatchDescription;

/** Internal GPU memory of a context. */
typedef struct FfxDofMemoryUsage {
    uint64_t totalUsageInBytes;     /**< every internal image and buffer, as the driver sized them */
    uint64_t aliasableUsageInBytes; /**< the part that holds nothing between dispatches */
} FfxDofMemoryUsage;

/** Creates a context. On success *pContext receives a new handle; on failure it is set to NULL
 *  (when pContext itself is not NULL). Records no GPU work. */
FfxDofErrorCode ffxDofContextCreate(FfxDofContext* pContext, const FfxDofContextDescription* pContextDescription);

/** Records the five passes into pDispatchDescription->commandList. */
FfxDofErrorCode ffxDofContextDispatch(FfxDofContext* pContext, const FfxDofDispatchDescription* pDispatchDescription);

/** Destroys the context and sets *pContext to NULL. The GPU must have finished every dispatch
 *  recorded with it. Destroying a NULL handle returns FFX_DOF_OK. */
FfxDofErrorCode ffxDofContextDestroy(FfxDofContext* pContext);

/** Autofocus forgets the distance it has been smoothing (a camera cut): the next autofocus dispatch
 *  focuses at once. */
FfxDofErrorCode ffxDofContextResetAutofocus(FfxDofContext* pContext);

/** The focus distance autofocus chose in the dispatch recorded dispatchesAgo dispatches before the
 *  latest one (0 = the latest), without waiting: the caller says that dispatch has finished on the
 *  GPU. maxFramesInFlight (see the backend description) is always safe while recording the next
 *  frame; 0 is right after the engine waited for the GPU. Positive, in the unit of the lens. Returns
 *  FFX_DOF_ERROR_INVALID_ARGUMENT when that dispatch did not run autofocus or is not kept (at most
 *  maxFramesInFlight dispatches back). */
FfxDofErrorCode ffxDofContextGetAutofocusDistance(FfxDofContext* pContext, uint32_t dispatchesAgo, float* pDistance);

/** Bytes of internal GPU memory the context holds. */
FfxDofErrorCode ffxDofContextGetGpuMemoryUsage(FfxDofContext* pContext, FfxDofMemoryUsage* pVramUsage);

/** Destroys a backend. Returns FFX_DOF_ERROR_BACKEND_IN_USE (and destroys nothing) while contexts
 *  made with it are alive, and FFX_DOF_ERROR_INVALID_ARGUMENT (reading nothing) for a backend that
 *  was destroyed already or is no backend. NULL is accepted. */
FfxDofErrorCode ffxDofBackendDestroy(FfxDofBackend backend);

/** FFX_DOF_MAKE_VERSION of this library. */
FfxDofVersionNumber ffxDofGetEffectVersion(void);

/** A static English sentence for a code, e.g. "quality is 0 or above FFX_DOF_MAX_QUALITY". */
const char* ffxDofGetErrorString(FfxDofErrorCode code);

/** The detail of the last error on this thread (which field, which API call), or "". */
const char* ffxDofGetLastErrorMessage(void);

/**
 * Circle-of-confusion scale and bias for FfxDofDispatchDescription, from the thin-lens model:
 *
 *   radius = |A * f * (F - Z)| / (Z * (F - f))     [sensor units]
 *
 * with A the aperture radius, f the focal length, F the focus distance and Z the view distance
 * of the object. With device depth d and Z = proj34 / (d - proj33) ... the radius becomes an
 * affine function of d: radius = d * scale + bias (see docs/coc.md for the derivation).
 *
 * @param aperture   aperture radius, in the same unit as focalLength and focus (e.g. metres)
 * @param focus      distance of the plane in focus; negative when the camera looks down -Z
 * @param focalLength focal length
 * @param conversion sensor units to half-resolution pixels: 0.5 * imageWidth / sensorWidth
 * @param proj33, proj34, proj43 projection matrix terms (row, column, 1-based) mapping view z to
 *        clip z and clip w: clipZ = proj33 * z + proj34, clipW = proj43 * z
 */
float ffxDofCalculateCocScale(float aperture, float focus, float focalLength, float conversion, float proj33,
                              float proj34, float proj43);
float ffxDofCalculateCocBias(float aperture, float focus, float focalLength, float conversion, float proj33,
                             float proj34, float proj43);

#ifdef __cplusplus
}
#endif

#endif /* FFX_DOF_H */
