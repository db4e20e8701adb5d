// Illumination implementations (one call per light from the lighting shadings).
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

namespace volren {

namespace {

const ParameterDecl specular = {.key = "specular", .defaultValue = 0.3, .lo = 0.0, .hi = 10.0,
                                .help = "specular strength", .panel = {PanelHint::Slider, 0.0, 2.0}};

/// The phase functions' anisotropy (henyey_greenstein, schlick).
const ParameterDecl anisotropy = {.key = "anisotropy", .defaultValue = 0.0, .lo = -0.99, .hi = 0.99,
                                  .help = "phase function's g: 0 isotropic, > 0 forward, < 0 backward scattering",
                                  .label = "anisotropy g", .panel = {PanelHint::Slider, -0.9, 0.9}};

void bindAnisotropy(BindContext& c)
{
    c.uniform("volren_anisotropy", float(c.settings.number("anisotropy")));
}

}  // namespace

void registerIlluminationFunctions(ShaderFunctionRegistry& registry)
{
    registry.add({.slot = "Illumination",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("no light")});
    registry.add({.slot = "Illumination",
                  .name = "lambert",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("lambert diffuse"),
                  .benchRows = {{}}});
    registry.add({.slot = "Illumination",
                  .name = "blinn_phong",
                  .uniforms = {{"volren_specular", "float", ""}, {"volren_shininess", "float", ""}},
                  .parameters = {specular,
                                 {.key = "shininess", .defaultValue = 24.0, .lo = 1.0, .hi = 1e4,
                                  .help = "Blinn-Phong exponent", .panel = {PanelHint::LogSlider, 1.0, 256.0}}},
                  .bind =
                      [](BindContext& c) {
                          c.uniform("volren_specular", float(c.settings.number("specular")));
                          c.uniform("volren_shininess", float(c.settings.number("shininess")));
                      },
                  .traits = {.calls = SlotList{}, .aliases = {"blinnphong", "blinn-phong", "phong"}},
                  .reference = ReferenceModel::exact("diffuse + blinn-phong highlight")});
    registry.add({.slot = "Illumination",
                  .name = "cook_torrance",
                  .uniforms = {{"volren_specular", "float", ""}, {"volren_roughness", "float", ""}},
                  .parameters = {specular,
                                 {.key = "roughness", .defaultValue = 0.35, .lo = 0.0, .hi = 1.0, .openLow = true,
                                  .help = "Cook-Torrance surface roughness", .panel = {PanelHint::Slider, 0.02, 1.0}}},
                  .bind =
                      [](BindContext& c) {
                          c.uniform("volren_specular", float(c.settings.number("specular")));
                          c.uniform("volren_roughness", float(c.settings.number("roughness")));
                      },
                  .traits = {.calls = SlotList{}, .aliases = {"cooktorrance", "cook-torrance"}},
                  .reference = ReferenceModel::exact("diffuse + cook-torrance ggx highlight"),
                  .benchRows = {{}}});
    // Volume scattering (no normal): the phase function between the light and the view.
    registry.add({.slot = "Illumination",
                  .name = "henyey_greenstein",
                  .uniforms = {{"volren_anisotropy", "float", ""}},
                  .parameters = {anisotropy},
                  .bind = bindAnisotropy,
                  .traits = {.calls = SlotList{}, .aliases = {"hg", "phase", "henyeygreenstein", "scattering"}},
                  .reference = ReferenceModel::exact("henyey-greenstein phase")});
    // Schlick's approximation of it, without a power (Blasi, Le Saec and Schlick 1993): measured
    // against the reference's Henyey-Greenstein phase at the same g (ShadowingTest, |g| <= 0.5:
    // worst 0.067 of full scale, back-scattering at g = -0.5; 0.013 at |g| = 0.3).
    registry.add({.slot = "Illumination",
                  .name = "schlick",
                  .uniforms = {{"volren_anisotropy", "float", ""}},
                  .parameters = {anisotropy},
                  .bind = bindAnisotropy,
                  .traits = {.calls = SlotList{}, .aliases = {"schlick_phase"}},
                  .reference = ReferenceModel::approximate("henyey-greenstein phase", 0.08),
                  .benchRows = {{{"anisotropy", "0.5"}}}});
}

}  // namespace volren
