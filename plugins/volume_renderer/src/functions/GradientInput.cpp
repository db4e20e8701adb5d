// GradientInput implementations: the field a Gradient differentiates.
#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

void registerGradientInputFunctions(ShaderFunctionRegistry& registry)
{
    // null only where nothing reads a gradient (Gradient requires an input).
    registry.add({.slot = "GradientInput",
                  .name = "null",
                  .traits = {.calls = SlotList{}},
                  .reference = ReferenceModel::exact("no gradient")});
    registry.add({.slot = "GradientInput",
                  .name = "scalar",
                  .traits = {.calls = SlotList{"Reconstruction"}},
                  .reference = ReferenceModel::exact("scalar field")});
    registry.add({.slot = "GradientInput",
                  .name = "alpha",
                  .traits = {.calls = SlotList{"Reconstruction", "Classification"}},
                  .reference = ReferenceModel::none("the reference's normals come from the scalar field")});
}

}  // namespace volren
