// Shadowing implementations: the fraction of a light that reaches a sample.
#include "CommonBindings.h"

#include "../resources/LightVolume.h"
#include "../resources/OpacityMipChain.h"

#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/LoopBudget.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>
#include <volume_model/Volume.h>

#include <osg/Texture2DArray>
#include <osg/Texture3D>

#include <algorithm>
#include <cmath>

namespace volren {

using bindings::operator+;

namespace {

/// Every shadowing method reads the opaque geometry's shadow maps (Shadowing/geometry_shadow.glsl).
// The opaque geometry's shadow maps: the ray caster's only (a light volume's build ignores them).
// One map per light a volume uses.
constexpr unsigned int geometryMaps = CompositionPolicy::maxLights;
const std::vector<UniformDecl> geometryShadowUniforms = {
    {.name = "volren_geometryShadowCount", .glslType = "int", .rayCasterOnly = true},
    {.name = "volren_geometryShadowMatrix", .glslType = "mat4", .arraySize = std::to_string(geometryMaps), .rayCasterOnly = true},
    {.name = "volren_geometryShadowBias", .glslType = "float", .arraySize = std::to_string(geometryMaps), .rayCasterOnly = true}};
const TextureDecl geometryShadowTexture = {.name = "volren_geometryShadow", .samplerType = "sampler2DArray", .rayCasterOnly = true};

/// The maps' matrices from the volume's texture space and their depth bias (half a voxel along the
/// volume's axis where the map's depth changes fastest, in map depth at the box's centre), or
/// none to read (no opaque geometry).
void bindGeometryShadows(BindContext& c)
{
    const std::vector<osg::Matrixd>& maps = c.geometryShadowMatrices;
    auto map = c.aux.find("geometry shadow map");
    const int count = map == c.aux.end() ? 0 : int(std::min<std::size_t>(maps.size(), geometryMaps));
    c.uniform("volren_geometryShadowCount", count);
    for (int i = 0; i < count; ++i) {
        c.uniformElement("volren_geometryShadowMatrix", geometryMaps, unsigned(i), osg::Matrixf(maps[std::size_t(i)]));
        // Depth per texture unit along the light at this point: the map's depth slope, from the
        // matrix's third row against its fourth (w), at the box centre.
        const osg::Matrixd& m = maps[std::size_t(i)];
        const osg::Vec4d centre = osg::Vec4d(0.5, 0.5, 0.5, 1.0) * m;
        float bias = 0.0f;
        if (centre.w() > 0.0) {
            double slope = 0.0;
            for (int a = 0; a < 3; ++a) {
                const double dz = (m(a, 2) * centre.w() - centre.z() * m(a, 3)) / (centre.w() * centre.w());
                slope = std::max(slope, std::abs(dz) / c.volume.dims()[a]);  // per voxel along axis a
            }
            bias = float(0.5 * slope);
        }
        c.uniformElement("volren_geometryShadowBias", geometryMaps, unsigned(i), bias);
    }
    // A sampler must name a texture of its type on its own unit even where it is never read.
    static const osg::ref_ptr<osg::Texture2DArray> none = [] {
        osg::ref_ptr<osg::Texture2DArray> t = new osg::Texture2DArray;
        t->setInternalFormat(GL_DEPTH_COMPONENT32F);
        t->setSourceFormat(GL_DEPTH_COMPONENT);
        t->setSourceType(GL_FLOAT);
        for (auto w : {osg::Texture::WRAP_S, osg::Texture::WRAP_T, osg::Texture::WRAP_R})
            t->setWrap(w, osg::Texture::CLAMP_TO_EDGE);  // OSG's default CLAMP is not core GL
        t->setTextureSize(1, 1, 1);
        return t;
    }();
    c.texture("volren_geometryShadow", count > 0 ? map->second.get() : none.get());
}

/// The opaque geometry's shadow maps are read only where there is opaque geometry to shadow a lit
/// volume (compiled out otherwise: a driver that runs a uniform branch's both sides, as llvmpipe,
/// paid for the lookup at every lit sample, a fifth of a light-volume frame).
const std::map<std::string, std::string> geometryShadowDefine = {{"VOLREN_GEOMETRY_SHADOWS", "0"}};
CompileOptions geometryShadowOption(const CompileContext& c)
{
    const bool on = c.offer.opaqueGeometry && c.composition.lightCount > 0;
    return {.defines = {{"VOLREN_GEOMETRY_SHADOWS", on ? "1" : "0"}}, .keyFragment = on ? "geometryShadows=1;" : ""};
}

/// The shadow march's step, shared by every method that marches towards the lights.
const ParameterDecl shadowStepFactor = {
    .key = "shadowStepFactor", .defaultValue = 1.0, .lo = 0.0, .hi = 1e3, .openLow = true,
    .help = "step of the marches towards the lights, as a factor of the view ray's step",
    .label = "shadow step factor", .panel = {PanelHint::LogSlider, 0.25, 8.0}};
/// Where a march towards a light stops.
const ParameterDecl shadowCutoff = {
    .key = "shadowCutoff", .defaultValue = 1.0 / 512.0, .lo = 0.0, .hi = 1.0,
    .help = "marches towards a light stop once its transmittance falls below this (0 = never; default 1/512)",
    .label = "shadow cutoff", .panel = {PanelHint::LogSlider, 1e-4, 0.5}};
/// The cones' shape and march (cone and cone_ao).
const std::vector<ParameterDecl> coneParameters = {
    shadowStepFactor,
    shadowCutoff,
    {.key = "coneAngle", .defaultValue = 10.0, .lo = 0.0, .hi = 120.0, .openLow = true, .unit = "degrees",
     .help = "the shadow cones' full aperture", .label = "cone angle (degrees)",
     .panel = {PanelHint::LogSlider, 0.5, 90.0}},
    {.key = "coneStart", .defaultValue = 0.5, .lo = 0.0, .hi = 16.0, .unit = "voxels",
     .help = "where the cones start, from the sample (its own neighbourhood casts no shadow on it)",
     .label = "cone start (voxels)", .panel = {PanelHint::Slider, 0.0, 8.0}},
    {.key = "coneStepGrowth", .defaultValue = 1.25, .lo = 0.05, .hi = 4.0,
     .help = "each cone step as a fraction of the cone's diameter there (1.25: the error of 1 at less time)",
     .label = "cone step growth", .panel = {PanelHint::LogSlider, 0.25, 4.0}},
    {.key = "coneFilterSigma", .defaultValue = 0.0, .lo = 0.0, .hi = 4.0, .unit = "voxels",
     .help = "sigma of the Gaussian pre-filter of the opacity volume (0 = none)",
     .label = "cone filter sigma (voxels)", .panel = {PanelHint::Slider, 0.0, 3.0}}};
/// How far ambient occlusion looks (cone_ao).
const ParameterDecl aoDistance = {
    .key = "aoDistance", .defaultValue = 8.0, .lo = 0.0, .hi = 256.0, .openLow = true, .unit = "voxels",
    .help = "reach of the ambient-occlusion cones", .label = "occlusion distance (voxels)",
    .panel = {PanelHint::LogSlider, 1.0, 64.0}};

}  // namespace

void registerShadowingFunctions(ShaderFunctionRegistry& registry)
{
    // The depth of the scene's opaque geometry seen from each light (up to four; a 2D array
    // texture compared LEQUAL, one layer per light) over the boxes of the volumes that read it,
    // drawn before the frame by the pass (GeometryShadowMaps), with
    // BindContext::geometryShadowMatrices: polygons shadow the volumes.
    registry.addAuxKind({.name = "geometry shadow map", .scope = AuxScope::GeometryFromLights});
    // Per node, each light's transmittance (one half-float channel per light, four per layer, two
    // layers) over the volume's box at lightVolumeScale of the sampled level's resolution, edges
    // repeated outside; built slice by slice (light_volume_build.comp, LightVolume.h) when the
    // lights or what the classified volume depends on change. It also darkens the opaque
    // geometry inside the box (ShadowedGeometry).
    registry.addAuxKind({.name = "light volume",
                         .build = AuxBuild{.sampler = "volren_lightVolume",
                                           .readsLights = true,
                                           .dims =
                                               [](const osg::Vec3i& level, const BindContext& c) {
                                                   osg::Vec3i d = lightVolumeDims(level, c.settings.number("lightVolumeScale"));
                                                   d.z() *= lightVolumeLayers(c.lights.size());  // lights 4-7 in a second layer
                                                   return d;
                                               },
                                           .channels = [](const BindContext& c) { return lightVolumeChannels(c.lights.size()); },
                                           .plan = [](const BindContext& c, const osg::Vec3d& size,
                                                      const osg::Vec3i& dims) { return lightVolumePlan(c.lights, size, dims); }},
                         .darkensGeometry = true});
    // Per node, the classified extinction (per world unit) at every voxel of the sampled level, as
    // a half-float 3D texture with a full mip chain (box-filtered on the GPU, zero outside the
    // box, read from the nearest level: cone steps then fetch half the texels of blending two,
    // which on llvmpipe cost cones a third of their time, at RMSE within 2% of it), built when the
    // TF, the volume or a clip shape changes (cone_build.comp, OpacityMipChain.h).
    registry.addAuxKind(
        {.name = "opacity mip chain",
         .build = AuxBuild{.sampler = "volren_opacityMips",
                           .mipmapped = true,
                           .wrap = osg::Texture::CLAMP_TO_BORDER,
                           .minFilter = osg::Texture::LINEAR_MIPMAP_NEAREST,
                           .dims = [](const osg::Vec3i& level, const BindContext&) { return level; },
                           .plan = [](const BindContext&, const osg::Vec3d&, const osg::Vec3i& dims) { return opacityVolumePlan(dims); }}});

    registry.add({.slot = "Shadowing",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("unshadowed")});

    // Shadow rays: a march towards each light per lit sample, with the view ray's sampling.
    registry.add({.slot = "Shadowing",
                  .name = "ray",
                  .includes = {"Shadowing/geometry_shadow.glsl"},
                  .uniforms = bindings::geometry + geometryShadowUniforms +
                              std::vector<UniformDecl>{{"volren_shadowStep", "float", ""},
                                                       {"volren_referenceStep", "float", ""},
                                                       {"volren_shadowCutoffDepth", "float", ""}},
                  .textures = {geometryShadowTexture},
                  .needs = {"geometry shadow map"},
                  .parameters = {shadowStepFactor, shadowCutoff},
                  .defines = geometryShadowDefine,
                  .compileOptions = geometryShadowOption,
                  .bind =
                      [](BindContext& c) {
                          bindings::bindGeometry(c);
                          bindGeometryShadows(c);
                          // On llvmpipe every view sample's march shares one loop budget per pixel.
                          const double step = c.sampleDistance * c.settings.number("shadowStepFactor");
                          c.uniform("volren_shadowStep", float(shadowStepWithinLoopLimit(c, step)));
                          c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
                          const double cutoff = c.settings.number("shadowCutoff");
                          c.uniform("volren_shadowCutoffDepth", float(cutoff > 0.0 ? -std::log(cutoff) : 1e30));
                      },
                  .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition", "Weighting"},
                             .clipsPerSample = true,
                             .aliases = {"shadowray", "shadow_ray", "rays"}},
                  // The definition itself: the transmittance to each light, marched.
                  .reference = ReferenceModel::exact("exact shadows"),
                  // At least one step per light; its bind lengthens the step to fit the rest
                  // of a pixel's loop budget (shadowStepWithinLoopLimit).
                  .loops = [](const BindContext&) { return LoopCost{.perLight = 1.0}; }});

    // Propagated light volume: each light's transmittance in a half-float volume, built on the GPU
    // slice by slice (light_volume_build.comp) whenever the light, the TF, the volume or a clip
    // shape changes, read with one trilinear fetch per lit sample.
    registry.add({.slot = "Shadowing",
                  .name = "light_volume",
                  .buildFile = "Shadowing/light_volume_build.comp",
                  .includes = {"Shadowing/geometry_shadow.glsl", "Shadowing/light_volume_layers.glsl"},
                  .uniforms = bindings::geometry + bindings::lights + geometryShadowUniforms +
                              std::vector<UniformDecl>{{"volren_shadowStep", "float", ""}, {"volren_referenceStep", "float", ""}},
                  .textures = {{"volren_lightVolume", "sampler3D"}, geometryShadowTexture},
                  .needs = {"light volume", "geometry shadow map"},
                  .parameters = {shadowStepFactor,
                                 {.key = "lightVolumeScale", .defaultValue = 0.5, .lo = 0.0, .hi = 1.0, .openLow = true,
                                  .help = "resolution of the light volume as a fraction of the volume's along each axis",
                                  .label = "light volume scale", .panel = {PanelHint::Slider, 0.1, 1.0}}},
                  .defines = geometryShadowDefine,
                  .compileOptions = geometryShadowOption,
                  .bind =
                      [](BindContext& c) {
                          bindings::bindGeometry(c);
                          bindGeometryShadows(c);
                          // The build integrates the full-resolution classification along each
                          // path at the view ray's step (times the shadow step factor).
                          c.uniform("volren_shadowStep", float(c.sampleDistance * c.settings.number("shadowStepFactor")));
                          c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
                          c.texture("volren_lightVolume", c.aux.at("light volume").get());
                      },
                  .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition", "Weighting"},
                             .clipsPerSample = true,
                             .aliases = {"lightvolume", "light-volume", "propagated"}},
                  // Trilinear in a half-resolution light volume: within 4e-3 on MultiVolumeShadows'
                  // soft blobs; 0.13 on the composition sweep's dense lit shell under a phase
                  // function (16x16, apps/volren/SweepHarness.cpp), which the bound covers.
                  .reference = ReferenceModel::approximate("exact shadows", 0.15)});

    // Cone tracing through the opacity mip chain: soft shadows (cone), and with directional
    // ambient occlusion (cone_ao). The chain is built on the GPU (cone_build.comp, then
    // box-filtered levels) when the TF, the volume or a clip shape changes; lights are free.
    const std::vector<UniformDecl> coneUniforms =
        bindings::geometry + geometryShadowUniforms + std::vector<UniformDecl>{{"volren_shadowStep", "float", ""},
                                                      {"volren_referenceStep", "float", ""},
                                                      {"volren_shadowCutoffDepth", "float", ""},
                                                      {"volren_coneVoxel", "float", ""},
                                                      {"volren_coneAngle", "float", ""},
                                                      {"volren_coneStart", "float", ""},
                                                      {"volren_coneStepGrowth", "float", ""},
                                                      {"volren_coneFilterSigma", "float", ""},
                                                      {"volren_aoDistance", "float", ""}};
    auto bindCone = [](BindContext& c) {
        bindings::bindGeometry(c);
        bindGeometryShadows(c);
        c.uniform("volren_shadowStep", float(c.sampleDistance * c.settings.number("shadowStepFactor")));
        c.uniform("volren_referenceStep", float(c.volume.minSpacing()));
        const double cutoff = c.settings.number("shadowCutoff");
        c.uniform("volren_shadowCutoffDepth", float(cutoff > 0.0 ? -std::log(cutoff) : 1e30));
        // One voxel of the chain's finest level (the sampled level), its smallest extent.
        const osg::Vec3d size = c.volume.worldSize();
        const osg::Texture3D& chain = static_cast<const osg::Texture3D&>(*c.aux.at("opacity mip chain"));
        const double voxel = std::min({size.x() / chain.getTextureWidth(), size.y() / chain.getTextureHeight(),
                                       size.z() / chain.getTextureDepth()});
        c.uniform("volren_coneVoxel", float(voxel));
        c.uniform("volren_coneAngle", float(osg::DegreesToRadians(c.settings.number("coneAngle"))));
        c.uniform("volren_coneStart", float(c.settings.number("coneStart")));
        c.uniform("volren_coneStepGrowth", float(c.settings.number("coneStepGrowth")));
        c.uniform("volren_coneFilterSigma", float(c.settings.number("coneFilterSigma")));
        c.uniform("volren_aoDistance", float(c.settings.number("aoDistance") * voxel));
        c.texture("volren_opacityMips", c.aux.at("opacity mip chain").get());
    };
    std::vector<ParameterDecl> withAoDistance = coneParameters;
    withAoDistance.push_back(aoDistance);
    // Steps of a cone over `distance` world units, at most (cone_march.glsl): each at least the
    // shadow step and coneStepGrowth voxels of the sampled level (the chain's finest voxel is
    // no smaller), 4096 at most.
    auto coneSteps = [](const BindContext& c, double distance) {
        const double voxel = std::ldexp(c.volume.minSpacing(), c.lod);
        const double step = std::max(c.sampleDistance * c.settings.number("shadowStepFactor"),
                                     c.settings.number("coneStepGrowth") * voxel);
        return std::min(4096.0, std::ceil(distance / std::max(step, 1e-30)) + 1.0);
    };
    const std::function<LoopCost(const BindContext&)> coneLoops = [coneSteps](const BindContext& c) {
        return LoopCost{.perLight = coneSteps(c, c.volume.worldSize().length())};
    };
    const std::function<LoopCost(const BindContext&)> coneAoLoops = [coneSteps](const BindContext& c) {
        // and five occlusion cones per sample
        const double ao = c.settings.number("aoDistance") * std::ldexp(c.volume.minSpacing(), c.lod);
        return LoopCost{.perSample = 5.0 * coneSteps(c, ao), .perLight = coneSteps(c, c.volume.worldSize().length())};
    };
    for (const char* name : {"cone", "cone_ao"})
        registry.add({.slot = "Shadowing",
                      .name = name,
                      .buildFile = "Shadowing/cone_build.comp",
                      .includes = {"Shadowing/geometry_shadow.glsl", "Shadowing/cone_march.glsl"},
                      .uniforms = coneUniforms,
                      .textures = {{"volren_opacityMips", "sampler3D"}, geometryShadowTexture},
                      .needs = {"opacity mip chain", "geometry shadow map"},
                      .parameters = std::string(name) == "cone" ? coneParameters : withAoDistance,
                      .defines = geometryShadowDefine,
                      .compileOptions = geometryShadowOption,
                      .bind = bindCone,
                      .traits = {.calls = SlotList{"Reconstruction", "Classification", "ClipPosition", "Weighting"},
                                 .clipsPerSample = true,
                                 .aliases = std::string(name) == "cone" ? std::vector<std::string>{"cones", "cone_shadows"}
                                                                        : std::vector<std::string>{"cones_ao", "cone+ao"}},
                      // Filtered opacity along a cone: within 5e-3 on MultiVolumeShadows' soft blobs;
                      // 0.11 on the composition sweep's dense lit shell (SweepHarness.cpp).
                      .reference = ReferenceModel::approximate(
                          std::string(name) == "cone" ? "exact shadows" : "exact shadows and occlusion", 0.13),
                      .loops = std::string(name) == "cone" ? coneLoops : coneAoLoops});
}

}  // namespace volren
