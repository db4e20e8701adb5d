// Propagated light volumes: each light's transmittance written slice by slice by
// Shadowing/light_volume_build.comp, swept along the axis most aligned with the light, nearest
// the light first.
#include "LightVolume.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace volren {

namespace {

constexpr int maxLights = lightVolumeMaxLights;
constexpr int groupSize = 8;  // local_size_x and _y of the build shader

}  // namespace

osg::Vec3i lightVolumeDims(const osg::Vec3i& dims, double scale)
{
    osg::Vec3i out;
    for (int a = 0; a < 3; ++a) out[a] = std::max(2, int(std::lround(dims[a] * std::clamp(scale, 1e-3, 1.0))));
    return out;
}

int lightVolumeLayers(std::size_t lights)
{
    return lights > 4 ? 2 : 1;
}

int lightVolumeChannels(std::size_t lights)
{
    const int n = int(std::clamp<std::size_t>(lights, 1, maxLights));
    return n >= 3 ? 4 : n;
}

osg::Vec4d lightInTextureSpace(const LightInfo& light, const osg::Vec3d& worldSize)
{
    const osg::Vec4d& l = light.position;
    osg::Vec4d t(0, 0, 0, l.w() == 0.0 ? 0.0 : 1.0);
    for (int a = 0; a < 3; ++a) t[a] = l.w() == 0.0 ? l[a] / worldSize[a] : l[a] / l.w() / worldSize[a] + 0.5;
    return t;
}

std::vector<BuildDispatch> lightVolumePlan(const std::vector<LightInfo>& lights, const osg::Vec3d& worldSize,
                                           const osg::Vec3i& texture)
{
    osg::Vec3i dims = texture;  // one layer's
    dims.z() /= lightVolumeLayers(lights.size());
    std::vector<BuildDispatch> plan;
    for (std::size_t i = 0; i < lights.size() && i < std::size_t(maxLights); ++i) {
        // Where the light is in texture space (a point light) or where it comes from (directional).
        const osg::Vec4d light = lightInTextureSpace(lights[i], worldSize);
        osg::Vec3d towards(light.x(), light.y(), light.z());
        if (light.w() != 0.0) towards -= osg::Vec3d(0.5, 0.5, 0.5);
        int axis = 2;
        double best = -1.0;
        for (int a = 0; a < 3; ++a)
            if (const double advance = std::abs(towards[a]) * dims[a]; advance > best) best = advance, axis = a;
        const int n = dims[axis];
        std::vector<int> slices(static_cast<std::size_t>(n));
        std::iota(slices.begin(), slices.end(), 0);
        if (light.w() == 0.0) {
            if (towards[axis] > 0.0) std::reverse(slices.begin(), slices.end());
        } else {  // outwards from the light's plane, which may cut the volume
            const double c = light[axis];
            std::stable_sort(slices.begin(), slices.end(),
                             [&](int a, int b) { return std::abs((a + 0.5) / n - c) < std::abs((b + 0.5) / n - c); });
        }
        const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
        const osg::Vec3i groups((dims[u] + groupSize - 1) / groupSize, (dims[v] + groupSize - 1) / groupSize, 1);
        for (int slice : slices)
            plan.push_back({{{"volren_buildLight", int(i)}, {"volren_buildAxis", axis}, {"volren_buildSlice", slice}}, groups});
    }
    return plan;
}

}  // namespace volren
