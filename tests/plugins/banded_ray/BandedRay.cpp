// The Shadowing "banded_ray", registered from $VOLREN_FUNCTION_PATH: everything volren knows of
// it is declared here.
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/Volume.h>

extern "C" void volrenRegisterShaderFunctions(volren::ShaderFunctionRegistry& registry)
{
    using namespace volren;
    // Its auxiliary volume: the classified extinction per world unit at the centre of every voxel
    // of the sampled level (zero where a clip shape removes it), one half float each, built on
    // the GPU by shaders/Shadowing/banded_ray_build.comp in one dispatch of 4x4x4 groups when the
    // volume, the TF, the level or a clip shape changes (not the lights or the band count).
    registry.addAuxKind({.name = "band extinction",
                         .build = AuxBuild{.sampler = "volren_bandExtinction",
                                           .dims = [](const osg::Vec3i& level, const BindContext&) { return level; },
                                           .plan = [](const BindContext&, const osg::Vec3d&, const osg::Vec3i& dims) {
                                               const osg::Vec3i groups((dims.x() + 3) / 4, (dims.y() + 3) / 4, (dims.z() + 3) / 4);
                                               return std::vector<BuildDispatch>{{.uniforms = {}, .groups = groups}};
                                           }}});
    registry.add({.slot = "Shadowing",
                  .name = "banded_ray",
                  .buildFile = "Shadowing/banded_ray_build.comp",
                  .uniforms = {{"volren_worldSize", "vec3", ""},
                               {"volren_referenceStep", "float", ""},
                               {.name = "volren_bandCount", .glslType = "int", .rayCasterOnly = true}},
                  .textures = {{"volren_bandExtinction", "sampler3D"}},
                  .needs = {"band extinction"},
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
                          c.texture("volren_bandExtinction", c.aux.at("band extinction").get());
                      },
                  .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition", "Weighting"},
                             .clipsPerSample = true},
                  // Midpoint segments through trilinear extinction: exact in homogeneous media,
                  // within this of exact shadows in the test's block at 8 segments.
                  .reference = ReferenceModel::approximate("exact shadows", 4e-3),
                  .benchRows = {{}, {{"bandCount", "32"}}}});
}
