// Reconstruction (scalar fetch) implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerReconstructionFunctions(ShaderFunctionRegistry& registry)
{
    registry.add(ShaderFunction::plain("Reconstruction", "null"));
    for (const char* name : {"nearest", "trilinear", "tricubic"}) {
        ShaderFunction f;
        f.slot = "Reconstruction";
        f.name = name;
        f.file = std::string("Reconstruction/") + name + ".glsl";
        f.uniforms = bindings::geometry;
        f.textures = {bindings::volumeTexture};
        f.needs = {AuxData::VolumeTexture};
        f.bind = [](BindContext& c) {
            bindings::bindGeometry(c);
            bindings::bindVolumeTexture(c);
        };
        registry.add(f);
    }
}

}  // namespace volren
