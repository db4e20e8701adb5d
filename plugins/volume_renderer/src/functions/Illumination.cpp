// Illumination implementations (one call per light from the lighting shadings).
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/RenderSettings.h>

namespace volren {

void registerIlluminationFunctions(ShaderFunctionRegistry& registry)
{
    registry.add(ShaderFunction::plain("Illumination", "null"));
    registry.add(ShaderFunction::plain("Illumination", "lambert"));
    registry.add({"Illumination", "blinn_phong", "Illumination/blinn_phong.glsl", "", {},
                  {{"volren_specular", "float", ""}, {"volren_shininess", "float", ""}}, {}, {},
                  [](BindContext& c) {
                      c.uniform("volren_specular", float(c.settings.specular));
                      c.uniform("volren_shininess", float(c.settings.shininess));
                  },
                  false});
    registry.add({"Illumination", "cook_torrance", "Illumination/cook_torrance.glsl", "", {},
                  {{"volren_specular", "float", ""}, {"volren_roughness", "float", ""}}, {}, {},
                  [](BindContext& c) {
                      c.uniform("volren_specular", float(c.settings.specular));
                      c.uniform("volren_roughness", float(c.settings.roughness));
                  },
                  false});
}

void registerShadowingFunctions(ShaderFunctionRegistry& registry)
{
    registry.add(ShaderFunction::plain("Shadowing", "null"));
}

void registerAccelerationFunctions(ShaderFunctionRegistry& registry)
{
    registry.add(ShaderFunction::plain("Acceleration", "null"));
}

}  // namespace volren
