// Opaque polygons and volumes shadowing each other (Shadowing with opaque geometry). A block lit
// from above and in front (so that its zero-gradient normal, the view direction, is lit) with an
// opaque square in the plane y = 12 over the block's x < 0 half, seen edge-on by the camera: every
// way from the left half to the light crosses the square, none from the right half does. With no
// ambient light the left half's light is gone (its coverage stays), the right half is the image
// without the square.
#include "LitBlock.h"
#include "TestData.h"

#include <volume_reference/ReferenceSetup.h>

#include <osg/MatrixTransform>

#include <cmath>

namespace volren::test {
namespace {

class MixedShadows : public LitBlock
{
protected:
    /// The square x in [-20, 0], z in [-10, 30] at y = 12 (edge-on from +z), blended when asked.
    static osg::ref_ptr<osg::Node> squareOverTheLeftHalf(bool blended = false)
    {
        osg::ref_ptr<osg::MatrixTransform> place = new osg::MatrixTransform(
            osg::Matrixd::scale(10, 20, 1) * osg::Matrixd::rotate(osg::PI_2, osg::X_AXIS) * osg::Matrixd::translate(-10, 12, 10));
        place->addChild(flatSquare({0, 0, 0}, 1.0f, {0.2f, 0.8f, 0.2f, 1.0f}).get());
        if (blended) place->getOrCreateStateSet()->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
        return place;
    }
    /// renderOrthoFromPlusZ's camera for `scene` at `pixels` square over `viewHeight` world units.
    static ReferenceCamera orthoFromPlusZ(const osg::Node& scene, int pixels, double viewHeight)
    {
        ReferenceCamera camera;
        camera.width = camera.height = pixels;
        const double distance = 10.0 * (scene.getBound().radius() + 1.0), h = viewHeight / 2.0;
        camera.view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, distance), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
        camera.projection = osg::Matrixd::ortho(-h, h, -h, h, 1.0, 2.0 * distance);
        return camera;
    }
    /// The block (pixels 4..11, 2 units each; x < 0 is pixels 4..7), lit in `open`, keeps its
    /// coverage in `shadowed`; there its left half is black and its right half as in `open`.
    static void expectLeftHalfDark(const Pixels& open, const Pixels& shadowed)
    {
        for (int y = 4; y < 12; ++y) {
            for (int x = 4; x < 12; ++x) {
                const osg::Vec4 &a = open.at(x, y), &b = shadowed.at(x, y);
                ASSERT_GT(a.r(), 0.05f) << x << "," << y;  // lit without the square
                EXPECT_NEAR(b.a(), a.a(), 1e-6) << "coverage " << x << "," << y;
                for (int c = 0; c < 3; ++c) {
                    if (x < 8) EXPECT_LT(b[c], 1e-4f) << "left half " << x << "," << y;
                    else EXPECT_NEAR(b[c], a[c], 1e-5) << "right half " << x << "," << y;
                }
            }
        }
    }
    /// An empty group with the square's bounding sphere (so renderOrthoFromPlusZ frames alike).
    static osg::ref_ptr<osg::Node> invisibleBound()
    {
        osg::ref_ptr<osg::Group> g = new osg::Group;
        g->setInitialBound(squareOverTheLeftHalf()->getBound());
        return g;
    }
};

const std::vector<osg::Vec4> lightsAboveAndInFront = {{0, 1, 1, 0}, {0, 30, 30, 1}};  // directional, point

TEST_F(MixedShadows, AnOpaqueSquareBetweenTheLightAndTheBlockTakesItsLightWithEveryMethod)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    for (const char* method : {"ray", "light_volume", "cone", "cone_ao"}) {
        for (const osg::Vec4& light : lightsAboveAndInFront) {
            SCOPED_TRACE(std::string(method) + (light.w() == 0 ? " directional" : " point light"));
            // One live scene: the square joins it after a frame (as in `volren view`).
            osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), method, 1.0, {light});
            scene->addChild(invisibleBound().get());  // the same framing (bounding sphere) as with the square
            const Pixels open = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
            EXPECT_EQ(scene->compositionKeys()[0].find("geometryShadows=1;"), std::string::npos) << "no maps to read";
            scene->addChild(squareOverTheLeftHalf().get());
            const Pixels shadowed = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
            EXPECT_NE(scene->compositionKeys()[0].find("geometryShadows=1;"), std::string::npos) << "the maps compiled in";
            expectLeftHalfDark(open, shadowed);
        }
    }
}

TEST_F(MixedShadows, TheSquareTakesTheLightOfEachOfEightLights)
{
    // Eight lights, directional and point in turn, each blocked by the square from the left half:
    // every one needs its own depth map (the last four's layers too), or the left half shows it.
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    std::vector<osg::Vec4> lights;
    for (int i = 0; i < 8; ++i) lights.push_back(lightsAboveAndInFront[std::size_t(i % 2)]);
    for (const char* method : {"ray", "light_volume", "cone"}) {
        SCOPED_TRACE(method);
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), method, 1.0, lights);
        scene->addChild(invisibleBound().get());
        const Pixels open = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
        scene = lit(block.get(), tf.get(), method, 1.0, lights);
        scene->addChild(squareOverTheLeftHalf().get());
        const Pixels shadowed = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
        EXPECT_EQ(scene->geometryShadowMapDraws(), 8u) << "one map per light";
        expectLeftHalfDark(open, shadowed);
    }
}

TEST_F(MixedShadows, TheLightsDepthMapIsDrawnAgainOnlyWhenTheLightTheGeometryOrTheContextChanges)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), "ray", 1.0, {lightsAboveAndInFront[0]});
    osg::ref_ptr<osg::MatrixTransform> square = dynamic_cast<osg::MatrixTransform*>(squareOverTheLeftHalf().get());
    ASSERT_TRUE(square);
    scene->addChild(square.get());
    // Which half of the block (pixels 4..11; x < 0 is 4..7) is dark in each of its rows.
    auto darkHalf = [](const Pixels& img) {
        bool left = true, right = true;
        for (int y = 4; y < 12; ++y)
            for (int x = 4; x < 12; ++x) (x < 8 ? left : right) = (x < 8 ? left : right) && img.at(x, y).r() < 1e-4f;
        return left && !right ? "left" : right && !left ? "right" : left ? "both" : "none";
    };
    const Pixels first = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
    EXPECT_STREQ(darkHalf(first), "left");
    EXPECT_EQ(scene->geometryShadowMapDraws(), 1u);
    const Pixels again = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
    EXPECT_EQ(scene->geometryShadowMapDraws(), 1u) << "nothing changed: the map is kept";
    for (std::size_t i = 0; i < first.rgba.size(); ++i) ASSERT_EQ(again.rgba[i], first.rgba[i]) << i;

    square->setMatrix(square->getMatrix() * osg::Matrixd::translate(20, 0, 0));  // over the right half
    EXPECT_STREQ(darkHalf(renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0)), "right");
    EXPECT_EQ(scene->geometryShadowMapDraws(), 2u) << "a transform moved";

    // The same drawable, its vertices moved back over the left half (dirty() counts the change).
    struct FindGeometry : osg::NodeVisitor
    {
        osg::Geometry* found = nullptr;
        FindGeometry() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        void apply(osg::Geometry& g) override { found = &g; }
    } find;
    square->accept(find);
    ASSERT_TRUE(find.found);
    auto* corners = static_cast<osg::Vec3Array*>(find.found->getVertexArray());
    for (osg::Vec3& c : *corners) c.x() -= 2.0f;  // the transform scales x by 10: 20 units
    corners->dirty();
    find.found->dirtyGLObjects();  // its display list, where one is used
    find.found->dirtyBound();
    EXPECT_STREQ(darkHalf(renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0)), "left");
    EXPECT_EQ(scene->geometryShadowMapDraws(), 3u) << "vertices moved";

    dynamic_cast<osg::LightSource*>(scene->getChild(1))->getLight()->setPosition({0, 1, 1.05f, 0});  // still through the square
    EXPECT_STREQ(darkHalf(renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0)), "left");
    EXPECT_EQ(scene->geometryShadowMapDraws(), 4u) << "the light moved";

    renderer(16, 16, 4);  // a new renderer: a new context, which holds no map yet
    EXPECT_STREQ(darkHalf(renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0)), "left");
    EXPECT_EQ(scene->geometryShadowMapDraws(), 5u) << "a new context";
    renderer(16, 16, 1);
}

TEST_F(MixedShadows, BlendedGeometryAndUnshadowedVolumesIgnoreTheSquare)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    for (const auto& [method, blended] : {std::pair<const char*, bool>{"ray", true}, {"null", false}}) {
        SCOPED_TRACE(method);
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), method, 1.0, {lightsAboveAndInFront[0]});
        scene->addChild(invisibleBound().get());
        const Pixels open = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
        scene->addChild(squareOverTheLeftHalf(blended).get());
        const Pixels with = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
        for (std::size_t i = 0; i < open.rgba.size(); ++i)
            for (int c = 0; c < 4; ++c) ASSERT_NEAR(with.rgba[i][c], open.rgba[i][c], 1e-6) << i;
    }
}

TEST_F(MixedShadows, TheReferenceBlocksTheSameLightAndTheGpuFollowsIt)
{
    // The reference's exact test of each light path against the square's triangles, and the
    // shadow rays' image against it (at the view step's error).
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    for (const osg::Vec4& light : lightsAboveAndInFront) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), "ray", 1.0, {light});
        scene->addChild(squareOverTheLeftHalf().get());
        const ReferenceCamera camera = orthoFromPlusZ(*scene, 16, 32.0);
        ReferenceOptions options;
        options.tolerance = 1e-3;
        const ReferenceScene content = referenceScene(*scene);
        ASSERT_TRUE(content.occluders) << "the reference sees the square";
        const ReferenceImage truth = renderReference(content, camera, options);
        const Pixels gpu = renderOrthoFromPlusZ(scene.get(), 16, 16, 32.0);
        double sum = 0.0;
        for (int y = 4; y < 12; ++y) {
            for (int x = 4; x < 12; ++x) {
                for (int c = 0; c < 3; ++c) {
                    if (x < 8) EXPECT_EQ(truth.at(x, y, c), 0.0) << "left half " << x << "," << y;
                    else EXPECT_GT(truth.at(x, y, c), 0.01) << "right half " << x << "," << y;
                    sum += std::pow(gpu.at(x, y)[c] - truth.at(x, y, c), 2.0);
                }
            }
        }
        EXPECT_LT(std::sqrt(sum / (64 * 3)), 0.01) << "RMSE, light w = " << light.w();
    }
}

/// Length of the way from `p` along `d` (towards a point light at `light` when `toPoint`) inside
/// the block [-8, 8]^3.
double wayThroughBlock(const osg::Vec3d& p, const osg::Vec3d& towards, bool toPoint)
{
    const osg::Vec3d d = toPoint ? towards - p : towards;
    double t0 = 0.0, t1 = toPoint ? 1.0 : 1e30;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (std::abs(p[a]) > 8.0) return 0.0;
            continue;
        }
        const double u = (-8.0 - p[a]) / d[a], v = (8.0 - p[a]) / d[a];
        t0 = std::max(t0, std::min(u, v));
        t1 = std::min(t1, std::max(u, v));
    }
    return t1 > t0 ? (t1 - t0) * d.length() : 0.0;
}

TEST_F(MixedShadows, TheLightVolumeDarkensTheGeometryBehindTheBlockByItsTransmittanceToTheLight)
{
    // A black absorbing block (its own light adds nothing) in front of a white square at z = -12,
    // seen from +z: each square pixel shows white times exp(-sigma x the view's way through the
    // block) times the mean over the lights of exp(-sigma x the light's way through it). The
    // reference computes the same exactly; shadow rays leave the square alone (documented).
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0, 0, 0, float(alpha)));
    const std::vector<std::vector<osg::Vec4>> cases = {{{0, 0, 1, 0}},  // along the view, slanted, a point
                                                       {{1, 0, 1, 0}},
                                                       {{6, 0, 30, 1}},
                                                       {{0, 0, 1, 0}, {-1, 0, 0, 0}},  // the second misses
                                                       // six: the last two in the light volume's second layer
                                                       {{0, 0, 1, 0}, {0, 0, 1, 0}, {0, 0, 1, 0}, {0, 0, 1, 0}, {1, 0, 1, 0}, {6, 0, 30, 1}}};
    for (const std::vector<osg::Vec4>& lights : cases) {
        for (const char* method : {"light_volume", "ray"}) {
            SCOPED_TRACE(std::string(method) + ", " + std::to_string(lights.size()) + " light(s), first w " +
                         std::to_string(lights[0].w()) + " x " + std::to_string(lights[0].x()));
            const bool shadowsSquare = std::string(method) == "light_volume";
            osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), method, 1.0, lights);
            scene->addChild(flatSquare({0, 0, -12}, 15.0f, {1, 1, 1, 1}).get());
            const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 32.0);
            for (int y = 2; y < 30; ++y) {
                for (int x = 2; x < 30; ++x) {
                    const osg::Vec3d p(x + 0.5 - 16.0, y + 0.5 - 16.0, -12.0);
                    const bool behind = std::abs(p.x()) < 8.0 && std::abs(p.y()) < 8.0;
                    double light = 0.0;
                    for (const osg::Vec4& l : lights)
                        light += std::exp(-sigma * wayThroughBlock(p, osg::Vec3d(l.x(), l.y(), l.z()), l.w() != 0));
                    light = shadowsSquare ? light / double(lights.size()) : 1.0;
                    const double expected = std::exp(-sigma * (behind ? depthVoxels : 0.0)) * light;
                    ASSERT_NEAR(img.at(x, y).g(), expected, 0.01 * expected) << x << "," << y;
                    ASSERT_NEAR(img.at(x, y).a(), 1.0, 1e-6);
                }
            }
            if (!shadowsSquare || lights.size() > 1) continue;
            // The reference: the closed form within its tolerance, the GPU within RMSE 0.002 of it.
            const ReferenceCamera camera = orthoFromPlusZ(*scene, 32, 32.0);
            ReferenceOptions options;
            options.tolerance = 1e-4;
            const ReferenceSetup setup = referenceSetup(*scene, camera, options);
            const ReferenceImage truth = renderReference(setup.scene, camera, setup.options);
            double sum = 0.0;
            for (int y = 2; y < 30; ++y) {
                for (int x = 2; x < 30; ++x) {
                    const osg::Vec3d p(x + 0.5 - 16.0, y + 0.5 - 16.0, -12.0);
                    const bool behind = std::abs(p.x()) < 8.0 && std::abs(p.y()) < 8.0;
                    const osg::Vec4& l = lights[0];
                    const double expected =
                        std::exp(-sigma * ((behind ? depthVoxels : 0.0) +
                                           wayThroughBlock(p, osg::Vec3d(l.x(), l.y(), l.z()), l.w() != 0)));
                    ASSERT_NEAR(truth.at(x, y, 1), expected, 1e-3) << "reference " << x << "," << y;
                    sum += std::pow(img.at(x, y).g() - truth.at(x, y, 1), 2.0);
                }
            }
            EXPECT_LT(std::sqrt(sum / (28 * 28)), 0.002) << "RMSE against the reference";
        }
    }
}

}  // namespace
}  // namespace volren::test