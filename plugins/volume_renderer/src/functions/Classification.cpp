// Classification implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

namespace volren {

void registerClassificationFunctions(ShaderFunctionRegistry& registry)
{
    ShaderFunction none{"Classification", "null", "Classification/null.glsl", "", {}, bindings::window,
                        {}, {}, [](BindContext& c) { bindings::bindWindow(c); }, false};
    registry.add(none);

    ShaderFunction tf1d{"Classification", "tf1d", "Classification/tf1d.glsl", "", {}, bindings::window,
                        {{"volren_transferFunction", "sampler1D"}}, {AuxData::TransferFunctionTable}, nullptr, false};
    tf1d.bind = [](BindContext& c) {
        bindings::bindWindow(c);
        c.texture("volren_transferFunction", c.aux.at(AuxData::TransferFunctionTable).get());
    };
    registry.add(tf1d);

    ShaderFunction premultiplied{"Classification", "premultiplied", "Classification/premultiplied.glsl", "", {},
                                 bindings::window, {{"volren_premultipliedTable", "sampler1D"}},
                                 {AuxData::PremultipliedTable}, nullptr, false};
    premultiplied.bind = [](BindContext& c) {
        bindings::bindWindow(c);
        c.texture("volren_premultipliedTable", c.aux.at(AuxData::PremultipliedTable).get());
    };
    registry.add(premultiplied);

    ShaderFunction threshold = tf1d;
    threshold.name = "threshold";
    threshold.file = "Classification/threshold.glsl";
    threshold.uniforms.push_back({"volren_threshold", "float", ""});
    threshold.bind = [](BindContext& c) {
        bindings::bindWindow(c);
        c.uniform("volren_threshold", float(c.settings.threshold));
        c.texture("volren_transferFunction", c.aux.at(AuxData::TransferFunctionTable).get());
    };
    registry.add(threshold);
}

}  // namespace volren
