#include "OpacityMipChain.h"

#include <algorithm>

namespace volren {

std::vector<BuildDispatch> opacityVolumePlan(const osg::Vec3i& dims)
{
    constexpr int group = 4;  // local_size_x, _y and _z of the build shader
    std::vector<BuildDispatch> plan;
    osg::Vec3i d = dims;
    for (int level = 0;; ++level) {
        plan.push_back({{{"volren_buildLevel", level}},
                        osg::Vec3i((d.x() + group - 1) / group, (d.y() + group - 1) / group, (d.z() + group - 1) / group),
                        level});
        if (d.x() == 1 && d.y() == 1 && d.z() == 1) break;
        d = osg::Vec3i(std::max(1, d.x() / 2), std::max(1, d.y() / 2), std::max(1, d.z() / 2));  // GL's level sizes
    }
    return plan;
}

}  // namespace volren
