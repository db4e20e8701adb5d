#pragma once
// Internal to the pass: the depth maps of a VolumeScene's opaque geometry seen from each light
// (the auxiliary data kind "geometry shadow map"), through which the shadowing methods let polygons between a
// light and a volume shadow it.
#include <volume_renderer/BindContext.h>

#include <osg/BoundingBox>
#include <osg/Camera>
#include <osg/Group>
#include <osg/Texture2DArray>
#include <osgUtil/CullVisitor>

#include <cstdint>
#include <vector>

namespace volren {

/// One depth layer per light (the first eight, all that volumes use) of the opaque geometry below a VolumeScene,
/// drawn by pre-render cameras in the frames where it changed: a light's map is drawn again
/// only when its frustum, the drawables reached below the scene, their matrices or what their
/// arrays' and primitive sets' dirty() counts change (or the context has no map yet).
class GeometryShadowMaps
{
public:
    /// Texels per side of each map.
    static constexpr int size = 2048;

    GeometryShadowMaps();
    /// Culls the maps of `scene`'s children (its opaque geometry; volumes draw nothing there)
    /// for `lights` (VolumeScene coordinates) over `receivers` (the boxes of the volumes that
    /// read them, VolumeScene coordinates) into `cv`, so they are drawn before its camera.
    void cull(osgUtil::CullVisitor& cv, osg::Group& scene, const std::vector<LightInfo>& lights,
              const osg::BoundingBoxd& receivers);
    /// The depth array texture (one layer per light, border 1 = lit; compared in the shader).
    osg::Texture2DArray* texture() const { return _texture.get(); }
    /// Per light of the last cull: VolumeScene coordinates -> its map's [0,1]^3 coordinates; a
    /// zero matrix where no single map covers the receivers (a point light inside their box).
    const std::vector<osg::Matrixd>& matrices() const { return _matrices; }
    /// Maps drawn so far (one per light and frame where it had to be drawn again).
    unsigned int draws() const { return _draws; }

private:
    osg::ref_ptr<osg::Texture2DArray> _texture;
    std::vector<osg::ref_ptr<osg::Camera>> _cameras;
    std::vector<osg::Matrixd> _matrices;
    std::vector<std::uint64_t> _casters;     ///< what the maps were last drawn from (CasterSignature)
    std::vector<osg::Matrixd> _drawnFrom;    ///< per layer: the frustum it was last drawn with
    unsigned int _draws = 0;
};

}  // namespace volren
