#pragma once
#include <osg/Geometry>
#include <osg/MatrixTransform>
#include <osg/Program>
#include <osg/StateSet>
#include <osg/Texture2D>
#include <osgUtil/CullVisitor>

#include <map>
#include <utility>

namespace volren {

/// The screen-sized, per-camera parts of the VolumeScene pass, made only for compositions that
/// ask for them (the auxiliary data kinds "depth texture" and "entry points") and sized to each camera's viewport:
/// - the depth capture: after the opaque geometry (render bin 5) the depth buffer is copied
///   into a depth texture that ClipRay/depth reads;
/// - entry points: before the volumes (render bin 8) each rasterised volume's front faces store
///   their volume-space positions in an image of its own, then a memory barrier (bin 9).
/// Volumes draw in bin 10. Resources of cameras or volumes not seen for a few frames are freed.
class ScreenPasses
{
public:
    ScreenPasses();
    ~ScreenPasses();

    /// Starts the cull of one camera in cull traversal number `cullCount`.
    void beginCull(osgUtil::CullVisitor& cv, unsigned int cullCount);
    /// Schedules the depth capture for the camera being culled; returns the state that binds
    /// its texture on texture unit `unit` as volren_depthTexture.
    osg::StateSet* depthState(osgUtil::CullVisitor& cv, int unit);
    /// Schedules the front-face pass of the volume `key` (box `box`, placed by `matrix`) for the
    /// camera being culled; returns the state that binds its entry-point image.
    osg::StateSet* entryState(osgUtil::CullVisitor& cv, const void* key, osg::Geometry& box, const osg::Vec3d& boxSize,
                              const osg::Matrix& matrix);
    /// Frees what was not used in the last few cull traversals.
    void endCull(unsigned int cullCount);
    /// Screen-sized textures currently held (for tests of "only what is used").
    std::size_t textureCount() const;
    /// Bytes of GL storage those textures take (depth 4 per pixel, entry points 16).
    std::size_t textureBytes() const;

private:
    struct Capture;
    struct Entry;
    osg::Vec4i _viewport;
    const osg::Camera* _camera = nullptr;
    unsigned int _cull = 0;
    unsigned int _barrierScheduled = 0;
    float _frameStamp = 1.0f;
    std::map<const osg::Camera*, Capture> _captures;
    std::map<std::pair<const osg::Camera*, const void*>, Entry> _entries;
    osg::ref_ptr<osg::Program> _entryProgram;
    osg::ref_ptr<osg::Geode> _barrier;
};

}  // namespace volren
