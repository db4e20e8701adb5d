// Implementations with one planted fault each, registered from $VOLREN_FUNCTION_PATH: the
// composition sweep's harness must catch every one (FaultyFunctionsTest.cpp).
#include <volume_renderer/ShaderFunctionRegistry.h>

extern "C" void volrenRegisterShaderFunctions(volren::ShaderFunctionRegistry& registry)
{
    using namespace volren;
    const ImplementationTraits leaf{.calls = SlotList{}};
    // Its GLSL file does not exist: composing it throws.
    registry.add({.slot = "Classification", .name = "compose_fails", .file = "Classification/no_such_file.glsl", .traits = leaf});
    // Classifies everything as transparent: a volume drawn with it shows nothing.
    registry.add({.slot = "Classification", .name = "draws_nothing", .traits = leaf});
    // Every ray returns +Inf.
    registry.add({.slot = "RayTraversal", .name = "writes_inf", .traits = leaf});
    // Not a fault but a probe: its GLSL shows every value (a grey ramp), while its CPU mirror
    // (what the occupancy grids are made from) calls cells whose values stay below 0.5
    // invisible, so a skipping Acceleration that leaps over them draws less than none.
    registry.add({.slot = "Classification",
                  .name = "hidden_below_half",
                  .traits = leaf,
                  .mayShow = [](const BindContext&) -> std::function<bool(double, double)> {
                      return [](double, double hi) { return hi >= 0.5; };
                  }});
}
