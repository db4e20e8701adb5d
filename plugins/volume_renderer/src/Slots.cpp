#include <volume_renderer/Slots.h>

namespace volren {

const std::vector<SlotInfo>& slots()
{
    static const std::vector<SlotInfo> all = {
        {"Reconstruction", "trilinear"},
        {"Classification", "tf1d"},
        {"ClipPosition", "null"},
        {"Shading", "null"},
        {"Jitter", "null"},
        {"ClipRay", "null"},
        {"RayTraversal", "dvr_front_to_back"},
        {"RaySetup", "box_intersection"},
    };
    return all;
}

}  // namespace volren
