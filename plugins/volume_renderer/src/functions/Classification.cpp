// Classification implementations.
#include "CommonBindings.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

namespace volren {

using bindings::operator+;

void registerClassificationFunctions(ShaderFunctionRegistry& registry)
{
    const ImplementationTraits leaf{.calls = SlotList{}};
    registry.add({.slot = "Classification",
                  .name = "null",
                  .uniforms = bindings::window,
                  .bind = bindings::bindWindow,
                  .traits = leaf});

    registry.add({.slot = "Classification",
                  .name = "tf1d",
                  .uniforms = bindings::window,
                  .textures = {{"volren_transferFunction", "sampler1D"}},
                  .needs = {AuxData::TransferFunctionTable},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.texture("volren_transferFunction", c.aux.at(AuxData::TransferFunctionTable).get());
                      },
                  .traits = leaf});

    registry.add({.slot = "Classification",
                  .name = "premultiplied",
                  .uniforms = bindings::window,
                  .textures = {{"volren_premultipliedTable", "sampler1D"}},
                  .needs = {AuxData::PremultipliedTable},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.texture("volren_premultipliedTable", c.aux.at(AuxData::PremultipliedTable).get());
                      },
                  .traits = leaf});

    registry.add({.slot = "Classification",
                  .name = "threshold",
                  .uniforms = bindings::window + std::vector<UniformDecl>{{"volren_threshold", "float", ""}},
                  .textures = {{"volren_transferFunction", "sampler1D"}},
                  .needs = {AuxData::TransferFunctionTable},
                  .bind =
                      [](BindContext& c) {
                          bindings::bindWindow(c);
                          c.uniform("volren_threshold", float(c.settings.threshold));
                          c.texture("volren_transferFunction", c.aux.at(AuxData::TransferFunctionTable).get());
                      },
                  .traits = leaf});
}

}  // namespace volren
