#include <volume_renderer/Slots.h>

namespace volren {

const std::vector<SlotInfo>& slots()
{
    static const std::vector<SlotInfo> all = {
        {.name = "Reconstruction", .function = "volren_fetchScalar"},
        {.name = "VolumeStorage", .function = "volren_volumeSample"},
        {.name = "Classification", .function = "volren_classify"},
        {.name = "GradientInput", .function = "volren_gradientInput"},
        {.name = "Gradient", .function = "volren_gradient"},
        {.name = "Illumination", .function = "volren_illuminate"},
        {.name = "Shadowing", .function = "volren_shadow"},
        {.name = "Shading", .function = "volren_shade"},
        {.name = "ClipPosition",
         .function = "volren_clipPosition",
         .isTemplate = true,
         .signature = "bool volren_clipPosition(vec3 pos)",
         .call = "volren_clipPosition_{k}(pos)",
         .join = " || ",
         .wrap = "    return {calls};\n",
         .empty = "    return false;\n"},
        {.name = "Weighting", .function = "volren_weight"},
        {.name = "Acceleration", .function = "volren_skip"},  // per member of a set: each skips its own medium
        {.name = "Jitter", .function = "volren_jitter", .perSet = true},
        {.name = "ClipRay",
         .function = "volren_clipRay",
         .isTemplate = true,
         .signature = "void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar)",
         .call = "    volren_clipRay_{k}(origin, dir, tNear, tFar);\n",
         .wrap = "{calls}"},
        {.name = "RayTraversal", .function = "volren_traverse", .perSet = true},
        {.name = "RaySetup", .perSet = true},
    };
    return all;
}

const SlotInfo* findSlot(const std::string& name)
{
    for (const SlotInfo& s : slots())
        if (s.name == name) return &s;
    return nullptr;
}

}  // namespace volren
