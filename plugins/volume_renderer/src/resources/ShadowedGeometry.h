#pragma once
// Internal to the pass: the volumes' shadows on the opaque geometry. For each volume whose
// Shadowing shadows the geometry (ImplementationTraits::shadowsGeometry), a pass over the
// camera's viewport after the depth capture (bin 5) and the light volumes' builds (bin 6) and
// before the ray casters (bin 10) multiplies each opaque pixel's colour by the transmittance
// to the lights its light volume holds (Shadowing/shadowed_geometry.frag).
#include <volume_renderer/BindContext.h>

#include <osg/Camera>
#include <osg/Program>
#include <osg/Texture3D>
#include <osgUtil/CullVisitor>

#include <map>
#include <utility>
#include <vector>

namespace volren {

/// The full-viewport passes that darken the opaque geometry behind light-volume-shadowed volumes.
class ShadowedGeometry
{
public:
    ShadowedGeometry();
    ~ShadowedGeometry();

    /// Schedules, for the camera `cv` culls, the pass of `node` (its box `worldSize`, placed by
    /// `matrix` under the current model-view): its light volume `lightVolume`, its `lights`
    /// (node coordinates; the first lightVolumeMaxLights held), the depth that `depthState`
    /// binds on texture unit 0. `cullCount` numbers the cull traversal.
    void cull(osgUtil::CullVisitor& cv, const void* node, const osg::Vec3d& worldSize, osg::Texture3D* lightVolume,
              const std::vector<LightInfo>& lights, const osg::Matrix& matrix, osg::StateSet* depthState,
              unsigned int cullCount);
    /// Frees the passes of cameras or volumes not culled in the last few traversals.
    void endCull(unsigned int cullCount);
    /// Passes held (for tests of "only what is used").
    std::size_t count() const { return _passes.size(); }

private:
    struct Pass;
    std::map<std::pair<const osg::Camera*, const void*>, Pass> _passes;
    osg::ref_ptr<osg::Program> _program;
};

}  // namespace volren
