#include "BuiltVolumeKinds.h"

#include "LightVolume.h"
#include "OpacityMipChain.h"

#include <volume_model/RenderSettings.h>

namespace volren {

const std::vector<BuiltVolumeKind>& builtVolumeKinds()
{
    static const std::vector<BuiltVolumeKind> kinds = {
        {.aux = AuxData::LightVolume,
         .name = "light volume",
         .sampler = "volren_lightVolume",
         .readsLights = true,
         .mipmapped = false,
         .dims =
             [](const osg::Vec3i& level, const BindContext& c) {
                 osg::Vec3i d = lightVolumeDims(level, c.settings.number("lightVolumeScale"));
                 d.z() *= lightVolumeLayers(c.lights.size());  // lights 4-7 in a second layer
                 return d;
             },
         .channels = [](const BindContext& c) { return lightVolumeChannels(c.lights.size()); },
         .plan = [](const BindContext& c, const osg::Vec3d& size, const osg::Vec3i& dims) {
             return lightVolumePlan(c.lights, size, dims);
         }},
        {.aux = AuxData::OpacityMipChain,
         .name = "opacity mip chain",
         .sampler = "volren_opacityMips",
         .readsLights = false,
         .mipmapped = true,
         .dims = [](const osg::Vec3i& level, const BindContext&) { return level; },
         .channels = [](const BindContext&) { return 1; },
         .plan = [](const BindContext&, const osg::Vec3d&, const osg::Vec3i& dims) { return opacityVolumePlan(dims); }},
    };
    return kinds;
}

const BuiltVolumeKind* builtVolumeKind(AuxData aux)
{
    for (const BuiltVolumeKind& kind : builtVolumeKinds())
        if (kind.aux == aux) return &kind;
    return nullptr;
}

}  // namespace volren
