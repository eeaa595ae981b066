/*
 * ffx-dof Direct3D 12 backend. Valid C99 and C++ (C through the COBJMACROS-style vtables of d3d12.h).
 *
 * The engine owns the device, the command lists and its resources. The backend owns its root
 * signature and pipeline states; each context owns its internal resources and descriptor heap.
 */
#ifndef FFX_DOF_DX12_H
#define FFX_DOF_DX12_H

#include "ffx_dof.h"

#include <d3d12.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Bits of FfxDofBackendDescriptionDX12::flags. */
typedef enum FfxDofBackendFlagBitsDX12 {
    /** Never select the 16-bit (FFX_HALF) shaders even where the device supports native 16-bit ops. */
    FFX_DOF_DX12_DISABLE_FLOAT16 = (1 << 0),
    /** Never select the wave64 shaders even where every wave has 64 lanes. */
    FFX_DOF_DX12_DISABLE_WAVE64 = (1 << 1)
} FfxDofBackendFlagBitsDX12;

typedef struct FfxDofBackendDescriptionDX12 {
    ID3D12Device* device;       /**< the engine's; the backend holds a reference until destroyed */
    uint32_t maxFramesInFlight; /**< dispatches the GPU may still be executing when the next is
                                     recorded; 0 means 3 */
    uint32_t flags;             /**< FfxDofBackendFlagBitsDX12 */
} FfxDofBackendDescriptionDX12;

/** Creates a D3D12 backend. Returns FFX_DOF_ERROR_UNSUPPORTED when this build carries no DXIL
 *  (built without dxc) or the device lacks shader model 6.2. *pBackend is NULL on failure. */
FfxDofErrorCode ffxDofBackendCreateDX12(const FfxDofBackendDescriptionDX12* pDescription, FfxDofBackend* pBackend);

/** Wraps an engine resource. state is the state it is in before the dispatch and is left in after. */
FfxDofResource ffxDofGetResourceDX12(ID3D12Resource* resource, DXGI_FORMAT format, uint32_t width, uint32_t height,
                                     D3D12_RESOURCE_STATES state);

/** Wraps the engine's command list, which must be open and of type DIRECT or COMPUTE. */
FfxDofCommandList ffxDofGetCommandListDX12(ID3D12GraphicsCommandList* commandList);

#ifdef __cplusplus
}
#endif

#endif /* FFX_DOF_DX12_H */
