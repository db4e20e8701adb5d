#include <volume_renderer/Slots.h>

namespace volren {

const std::vector<SlotInfo>& slots()
{
    static const std::vector<SlotInfo> all = {
        {"Reconstruction", "trilinear", "volren_fetchScalar", false, "", "", "", "", ""},
        {"Classification", "tf1d", "volren_classify", false, "", "", "", "", ""},
        {"GradientInput", "scalar", "volren_gradientInput", false, "", "", "", "", ""},
        {"Gradient", "null", "volren_gradient", false, "", "", "", "", ""},
        {"Illumination", "null", "volren_illuminate", false, "", "", "", "", ""},
        {"Shadowing", "null", "volren_shadow", false, "", "", "", "", ""},
        {"Shading", "null", "volren_shade", false, "", "", "", "", ""},
        {"ClipPosition", "null", "volren_clipPosition", true, "bool volren_clipPosition(vec3 pos)",
         "volren_clipPosition_{k}(pos)", " || ", "    return {calls};\n", "    return false;\n"},
        {"Acceleration", "null", "volren_skip", false, "", "", "", "", ""},
        {"Jitter", "hash", "volren_jitter", false, "", "", "", "", ""},
        {"ClipRay", "null", "volren_clipRay", true,
         "void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar)",
         "    volren_clipRay_{k}(origin, dir, tNear, tFar);\n", "", "{calls}", ""},
        {"RayTraversal", "dvr_front_to_back", "volren_traverse", false, "", "", "", "", ""},
        {"RaySetup", "box_intersection", "", false, "", "", "", "", ""},
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
