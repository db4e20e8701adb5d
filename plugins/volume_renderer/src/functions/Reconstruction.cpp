// Reconstruction (scalar fetch) implementations.
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerReconstructionFunctions(ShaderFunctionRegistry& registry)
{
    ShaderFunction trilinear;
    trilinear.slot = "Reconstruction";
    trilinear.name = "trilinear";
    trilinear.file = "Reconstruction/trilinear.glsl";
    trilinear.textures = {{"volren_volume", "sampler3D"}};
    trilinear.needs = {AuxData::VolumeTexture};
    trilinear.bind = [](BindContext& c) { c.texture("volren_volume", c.aux.at(AuxData::VolumeTexture).get()); };
    registry.add(trilinear);
}

}  // namespace volren
