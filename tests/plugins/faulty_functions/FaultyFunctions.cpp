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
}
