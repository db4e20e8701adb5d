// Reconstruction (scalar fetch) implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerReconstructionFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Reconstruction", .name = "null", .traits = {.calls = SlotList{}}});
    for (const char* name : {"nearest", "trilinear", "tricubic"})
        registry.add({.slot = "Reconstruction",
                      .name = name,
                      .uniforms = bindings::geometry,
                      .textures = {bindings::volumeTexture},
                      .needs = {AuxData::VolumeTexture},
                      .bind =
                          [](BindContext& c) {
                              bindings::bindGeometry(c);
                              bindings::bindVolumeTexture(c);
                          },
                      .traits = {.calls = SlotList{}}});
}

}  // namespace volren
