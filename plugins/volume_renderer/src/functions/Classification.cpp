// Classification implementations.
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

namespace volren {

void registerClassificationFunctions(ShaderFunctionRegistry& registry)
{
    ShaderFunction tf1d;
    tf1d.slot = "Classification";
    tf1d.name = "tf1d";
    tf1d.file = "Classification/tf1d.glsl";
    tf1d.textures = {{"volren_transferFunction", "sampler1D"}};
    tf1d.uniforms = {{"volren_tfScaleOffset", "vec2"}};
    tf1d.needs = {AuxData::TransferFunctionTable};
    tf1d.bind = [](BindContext& c) {
        // texel v -> stored v*norm -> data stored*slope+intercept -> window t -> table texel centre.
        const double norm = normalisedScale(c.volume.type());
        const double lo = c.transfer.domainMin(), hi = c.transfer.domainMax();
        const double n = c.transfer.resolution();
        const double inner = (n - 1.0) / n;
        const double scale = norm * c.volume.rescaleSlope() / (hi - lo) * inner;
        const double offset = (c.volume.rescaleIntercept() - lo) / (hi - lo) * inner + 0.5 / n;
        c.uniform("volren_tfScaleOffset", osg::Vec2f(float(scale), float(offset)));
        c.texture("volren_transferFunction", c.aux.at(AuxData::TransferFunctionTable).get());
    };
    registry.add(tf1d);
}

}  // namespace volren
