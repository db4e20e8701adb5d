// A shader-function plugin library as a user would write one: loaded at run time from
// $VOLREN_FUNCTION_PATH, it adds a Jitter implementation with a uniform it binds itself.
#include <volume_renderer/ShaderFunctionRegistry.h>

extern "C" void volrenRegisterShaderFunctions(volren::ShaderFunctionRegistry& registry)
{
    volren::ShaderFunction f;
    f.slot = "Jitter";
    f.name = "plugin_constant";
    f.file = "Jitter/plugin_constant.glsl";
    f.uniforms = {{"volren_pluginJitter", "float", ""}};
    f.bind = [](volren::BindContext& c) { c.uniform("volren_pluginJitter", 0.5f); };
    registry.add(f);
}
