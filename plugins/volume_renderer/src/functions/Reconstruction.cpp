// Reconstruction (scalar fetch) implementations: filters over the voxels the VolumeStorage holds.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerReconstructionFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Reconstruction",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::none("it reads no value: the sweep's 'drawn' check is its test")});
    // Footprints: voxels beyond a sample's cell its weights (all >= 0) may reach.
    for (const auto& [name, footprint] : {std::pair{"nearest", 1}, {"trilinear", 1}, {"tricubic", 2}})
        registry.add({.slot = "Reconstruction",
                      .name = name,
                      .uniforms = bindings::geometry,
                      .bind = bindings::bindGeometry,
                      .traits = {.calls = SlotList{"VolumeStorage"}, .required = {"VolumeStorage"}, .footprint = footprint},
                      .reference = std::string(name) == "trilinear"
                                       ? ReferenceModel::exact("trilinear field")
                                       : ReferenceModel::none("the reference reconstructs trilinearly only"),
                      // The bench measures the others against the default (trilinear).
                      .benchRows = std::string(name) == "trilinear" ? std::vector<BenchRow>{} : std::vector<BenchRow>{{}}});
}

}  // namespace volren
