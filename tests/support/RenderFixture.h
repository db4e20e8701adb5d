#pragma once
#include <volume_renderer/OffscreenRenderer.h>

#include <volume_model/VolumeNode.h>

#include <osg/Vec4>

#include <gtest/gtest.h>

namespace volren::test {

/// RGBA float pixels of a rendered frame, row 0 at the bottom.
struct Pixels
{
    int width = 0, height = 0;
    std::vector<osg::Vec4> rgba;
    std::vector<float> depth;  ///< window depth per pixel, when depth read-back was on
    const osg::Vec4& at(int x, int y) const { return rgba[std::size_t(y) * width + x]; }
};

/// Headless renderer shared by the render tests of one process (one EGL context).
class RenderFixture : public ::testing::Test
{
public:
    /// The shared renderer, created at `width` x `height` with `samples` per pixel (re-created
    /// when either changes; samples 0: as the current one, 1 for a new one).
    static OffscreenRenderer& renderer(int width, int height, int samples = 0);

    /// Renders `scene` with an orthographic camera looking from +z down -z at the origin,
    /// showing `viewHeight` world units vertically; near/far fixed around the scene.
    static Pixels renderOrthoFromPlusZ(osg::Node* scene, int width, int height, double viewHeight,
                                       const osg::Vec3& background = {0, 0, 0});

    /// Renders with the given view and projection matrices, no automatic near/far.
    static Pixels render(osg::Node* scene, int width, int height, const osg::Matrixd& view,
                         const osg::Matrixd& projection, const osg::Vec3& background = {0, 0, 0});

    /// An opaque square of `colour` in the plane z = centre.z, 2 * halfSize wide, drawn with a
    /// flat-colour program (so it looks the same in compatibility and core profiles).
    static osg::ref_ptr<osg::Node> flatSquare(const osg::Vec3& centre, float halfSize, const osg::Vec4& colour);
    /// An opaque sphere (finely tessellated ShapeDrawable) of `colour`, drawn like flatSquare.
    static osg::ref_ptr<osg::Node> flatSphere(const osg::Vec3& centre, float radius, const osg::Vec4& colour);

    /// A VolumeNode showing `volume` through `tf`, jitter off unless asked.
    static osg::ref_ptr<VolumeNode> volumeNode(Volume* volume, TransferFunction* tf, bool jitter = false);
};

}  // namespace volren::test
