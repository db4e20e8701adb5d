// The Shadowing "banded_ray", registered from $VOLREN_FUNCTION_PATH: everything volren knows of
// it is declared here.
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/Volume.h>

extern "C" void volrenRegisterShaderFunctions(volren::ShaderFunctionRegistry& registry)
{
    using namespace volren;
    registry.add({.slot = "Shadowing",
                  .name = "banded_ray",
                  .uniforms = {{"volren_worldSize", "vec3", ""},
                               {"volren_referenceStep", "float", ""},
                               {"volren_bandCount", "int", ""}},
                  .parameters = {{.key = "bandCount",
                                  .type = ParameterType::Integer,
                                  .defaultValue = 8,
                                  .lo = 1,
                                  .hi = 256,
                                  .unit = "segments",
                                  .help = "banded shadow rays: segments from a sample to where the light enters the box",
                                  .label = "bands",
                                  .panel = {PanelHint::Slider, 1, 64}}},
                  .bind =
                      [](BindContext& c) {
                          c.uniform("volren_worldSize", osg::Vec3f(c.boxSize.length2() > 0.0 ? c.boxSize : c.volume.worldSize()));
                          c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
                          c.uniform("volren_bandCount", c.settings.parameter<int>("bandCount"));
                      },
                  .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition", "Weighting"},
                             .clipsPerSample = true},
                  // Midpoint segments: exact in homogeneous media, within this of exact shadows
                  // in the test's block at 8 segments.
                  .reference = ReferenceModel::approximate("exact shadows", 4e-3),
                  .benchRows = {{}, {{"bandCount", "32"}}}});
}
