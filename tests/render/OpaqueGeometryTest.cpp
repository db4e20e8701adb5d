// Opaque polygons inside and around a volume: the rays end at the geometry's depth (ClipRay
// depth), so the geometry shows attenuated by exactly the medium in front of it.
#include "RenderFixture.h"
#include "TestData.h"

#include <osg/BlendFunc>
#include <osg/Geode>
#include <osg/LightSource>
#include <osg/MatrixTransform>
#include <osg/ShapeDrawable>

#include <cmath>
#include <cstdlib>
#include <string>

namespace volren::test {
namespace {

/// A 16^3 homogeneous absorbing medium (black emission, opacity 0.2 per voxel of spacing 1)
/// centred at the origin, so light crossing d world units keeps 0.8^d of itself.
class OpaqueGeometry : public RenderFixture
{
protected:
    static constexpr double alpha = 0.2;
    static constexpr int n = 16;

    static osg::ref_ptr<VolumeScene> sceneWith(osg::Node* geometry)
    {
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        osg::ref_ptr<VolumeNode> node = volumeNode(constantVolume(VoxelType::UInt8, {n, n, n}, 100).get(),
                                                   constantTransferFunction(osg::Vec4(0, 0, 0, float(alpha))).get());
        node->settings.earlyTerminationThreshold = 1.0;  // exact transmittance behind the whole box
        scene->addChild(node.get());
        if (geometry) scene->addChild(geometry);
        return scene;
    }
    static double transmittance(double length) { return std::pow(1.0 - alpha, length); }
};

TEST_F(OpaqueGeometry, SquareInsideIsAttenuatedByTheMediumInFrontOfItOrthographic)
{
    for (const float z : {6.0f, 0.0f, -5.5f}) {
        osg::ref_ptr<VolumeScene> scene = sceneWith(flatSquare({0, 0, z}, 4.0f, osg::Vec4(1, 1, 1, 1)).get());
        // 40 x 40 pixels over 20 x 20 world units: the square covers pixel centres 12..27.
        const Pixels img = renderOrthoFromPlusZ(scene.get(), 40, 40, 20.0);
        ASSERT_NE(scene->compositionKeys()[0].find("ClipRay=[depth];"), std::string::npos) << scene->compositionKeys()[0];
        const double expected = transmittance(n / 2.0 - z);
        for (int y = 12; y < 28; ++y)
            for (int x = 12; x < 28; ++x) {
                ASSERT_NEAR(img.at(x, y).g(), expected, 2e-4) << "z " << z << " pixel " << x << "," << y;
                ASSERT_NEAR(img.at(x, y).a(), 1.0, 1e-6);
            }
        // Beside the square the whole depth of the box absorbs (nothing behind it: alpha only).
        EXPECT_NEAR(img.at(6, 20).a(), 1.0 - transmittance(n), 2e-4);
        EXPECT_NEAR(img.at(6, 20).g(), 0.0, 1e-6);
    }
}

TEST_F(OpaqueGeometry, SphereAtTheCentreIsAttenuatedByTheMediumInFrontOfEachPixelAndKeepsItsSilhouette)
{
    // Orthographic from +z: at distance r from the axis the sphere's front lies at
    // z = sqrt(R^2 - r^2), so the light from it crosses n/2 - z of the medium.
    const double radius = 5.0;
    osg::ref_ptr<VolumeScene> scene = sceneWith(flatSphere({0, 0, 0}, float(radius), osg::Vec4(1, 1, 1, 1)).get());
    const int size = 64;
    const double view = 20.0;  // world units across
    const Pixels img = renderOrthoFromPlusZ(scene.get(), size, size, view);
    int inside = 0, outside = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double px = (x + 0.5) * view / size - view / 2, py = (y + 0.5) * view / size - view / 2;
            const double r = std::sqrt(px * px + py * py);
            const double pixel = view / size;
            if (r < radius - pixel) {
                const double front = std::sqrt(radius * radius - r * r);
                ASSERT_NEAR(img.at(x, y).g(), transmittance(n / 2.0 - front), 2e-3) << x << "," << y << " r " << r;
                ASSERT_NEAR(img.at(x, y).a(), 1.0, 1e-6);
                ++inside;
            } else if (r > radius + pixel && std::abs(px) < n / 2.0 - pixel && std::abs(py) < n / 2.0 - pixel) {
                ASSERT_NEAR(img.at(x, y).g(), 0.0, 1e-6) << "no sphere outside its silhouette " << x << "," << y;
                ASSERT_NEAR(img.at(x, y).a(), 1.0 - transmittance(n), 2e-4);
                ++outside;
            }
        }
    EXPECT_GT(inside, 600);
    EXPECT_GT(outside, 1000);
}

TEST_F(OpaqueGeometry, MultisampledFramebufferKeepsTheAttenuationAndSmoothsTheSilhouette)
{
    // The sphere again, drawn into a 4x multisampled framebuffer: the depth the rays end at is
    // resolved from it (a plain copy is a GL error there), so inside the silhouette every pixel
    // is attenuated as before; on the silhouette partly covered pixels blend sphere and medium,
    // values a single-sampled frame never has (between 0 and the sphere's ~0.17).
    const double radius = 5.0;
    osg::ref_ptr<VolumeScene> scene = sceneWith(flatSphere({0, 0, 0}, float(radius), osg::Vec4(1, 1, 1, 1)).get());
    const int size = 64;
    const double view = 20.0, pixel = view / size;
    auto partlyCovered = [&](const Pixels& img) {
        int count = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const double px = (x + 0.5) * pixel - view / 2, py = (y + 0.5) * pixel - view / 2;
                const double r = std::sqrt(px * px + py * py);
                count += std::abs(r - radius) < pixel && img.at(x, y).g() > 0.01f && img.at(x, y).g() < 0.12f;
            }
        return count;
    };
    EXPECT_EQ(partlyCovered(renderOrthoFromPlusZ(scene.get(), size, size, view)), 0) << "single-sampled";

    renderer(size, size, 4);  // the renders below use it
    const Pixels img = renderOrthoFromPlusZ(scene.get(), size, size, view);
    ASSERT_EQ(renderer(size, size).samples(), 4);
    renderer(size, size, 1);  // the other tests draw single-sampled
    EXPECT_GT(partlyCovered(img), 20) << "multisampled: the silhouette is antialiased";
    int inside = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double px = (x + 0.5) * pixel - view / 2, py = (y + 0.5) * pixel - view / 2;
            const double r = std::sqrt(px * px + py * py);
            if (r >= radius - 2 * pixel) continue;
            const double front = std::sqrt(radius * radius - r * r);
            // One ray per pixel ends at the depth the resolve took, one sample's (up to half a pixel
            // diagonal from the centre): allow the attenuation's change over that distance.
            const double expected = transmittance(n / 2.0 - front);
            const double slope = expected * -std::log(1.0 - alpha) * r / front;  // |d expected / dr|
            ASSERT_NEAR(img.at(x, y).g(), expected, 2e-3 + slope * pixel * std::sqrt(0.5))
                << x << "," << y << " r " << r;
            ++inside;
        }
    EXPECT_GT(inside, 500);
}

TEST_F(OpaqueGeometry, ViewportResizesAndOffsetsKeepTheDepthMixingExact)
{
    // One camera whose viewport shrinks to an offset part of the framebuffer and grows back, as a
    // resized window's does: the depth texture follows the viewport's size and origin, so the
    // square at z = 0 shows through half the box (0.8^8) in every frame.
    osg::ref_ptr<VolumeScene> scene = sceneWith(flatSquare({0, 0, 0}, 4.0f, osg::Vec4(1, 1, 1, 1)).get());
    OffscreenRenderer& r = renderer(64, 64);
    r.setScene(scene.get());
    r.setBackground({0, 0, 0});
    r.camera()->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    r.camera()->setViewMatrix(osg::Matrixd::lookAt(osg::Vec3d(0, 0, 50), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0)));
    struct Frame { int x, y, w, h; };
    for (const Frame f : {Frame{0, 0, 64, 64}, Frame{10, 20, 32, 24}, Frame{3, 1, 61, 40}, Frame{0, 0, 64, 64}}) {
        r.camera()->setViewport(f.x, f.y, f.w, f.h);
        const double h = 10.0, w = h * f.w / f.h;  // 20 world units high
        r.camera()->setProjectionMatrix(osg::Matrixd::ortho(-w, w, -h, h, 1.0, 100.0));
        const FrameTiming timing = r.renderFrame();
        EXPECT_TRUE(timing.glErrors.empty());
        // OSG reads the viewport's pixels back into the image, which takes the viewport's size.
        ASSERT_EQ(r.image()->s(), f.w);
        ASSERT_EQ(r.image()->t(), f.h);
        const auto* rgba = reinterpret_cast<const osg::Vec4*>(r.image()->data());
        const osg::Vec4& centre = rgba[(f.h / 2) * f.w + f.w / 2];
        EXPECT_NEAR(centre.g(), transmittance(n / 2.0), 2e-4) << "viewport " << f.x << "," << f.y << " " << f.w << "x" << f.h;
        // Beside the square (6 units from the centre): the whole box absorbs, nothing behind.
        const osg::Vec4& beside = rgba[(f.h / 2) * f.w + f.w / 2 + int(std::lround(6.0 * f.h / 20.0))];
        EXPECT_NEAR(beside.g(), 0.0, 1e-6);
        EXPECT_NEAR(beside.a(), 1.0 - transmittance(n), 2e-4);
    }
    r.camera()->setViewport(0, 0, 64, 64);
}

TEST_F(OpaqueGeometry, MeshPartlyInsideAndPartlyOutsideTheBox)
{
    // A square at z = 4, 28 units wide, sticks out of the 16-unit box on both sides: inside the
    // box's footprint it shows through the 4 units in front of it, outside it is untouched.
    osg::ref_ptr<VolumeScene> scene = sceneWith(flatSquare({0, 0, 4.0f}, 14.0f, osg::Vec4(1, 1, 1, 1)).get());
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 40, 40, 40.0);  // 1 unit per pixel
    for (int x = 7; x < 33; ++x) {
        const double centre = x + 0.5 - 20.0;
        const double expected = std::abs(centre) < 8.0 ? transmittance(4.0) : 1.0;
        EXPECT_NEAR(img.at(x, 20).g(), expected, 2e-4) << "x " << centre;
        EXPECT_NEAR(img.at(x, 20).a(), 1.0, 1e-6);
    }
}

TEST_F(OpaqueGeometry, SquareBehindIsAttenuatedByTheWholeBoxAndInFrontNotAtAll)
{
    osg::ref_ptr<VolumeScene> behind = sceneWith(flatSquare({0, 0, -12.0f}, 4.0f, osg::Vec4(1, 0.5f, 0.25f, 1)).get());
    Pixels img = renderOrthoFromPlusZ(behind.get(), 40, 40, 20.0);
    EXPECT_NEAR(img.at(20, 20).r(), transmittance(n), 2e-4);
    EXPECT_NEAR(img.at(20, 20).b(), 0.25 * transmittance(n), 2e-4);

    osg::ref_ptr<VolumeScene> front = sceneWith(flatSquare({0, 0, 12.0f}, 4.0f, osg::Vec4(1, 0.5f, 0.25f, 1)).get());
    img = renderOrthoFromPlusZ(front.get(), 40, 40, 20.0);
    EXPECT_EQ(img.at(20, 20), osg::Vec4(1, 0.5f, 0.25f, 1)) << "nothing of the volume lies in front of it";
    EXPECT_NEAR(img.at(6, 20).a(), 1.0 - transmittance(n), 2e-4) << "the volume beside it is unchanged";
}

TEST_F(OpaqueGeometry, PerspectiveRaysEndAtTheSquareAlongTheirOwnSlantedPath)
{
    osg::ref_ptr<VolumeScene> scene = sceneWith(flatSquare({0, 0, -2.0f}, 6.0f, osg::Vec4(1, 1, 1, 1)).get());
    const int size = 48;
    const osg::Vec3d eye(3, -4, 30);
    const osg::Matrixd view = osg::Matrixd::lookAt(eye, osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    const osg::Matrixd projection = osg::Matrixd::perspective(40, 1, 5, 60);
    const Pixels img = render(scene.get(), size, size, view, projection);
    const osg::Matrixd toWorld = osg::Matrixd::inverse(view * projection);
    int checked = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // This pixel's ray from the eye, through its centre, meets z = 8 (box top) and z = -2.
            const osg::Vec3d ndc(2.0 * (x + 0.5) / size - 1.0, 2.0 * (y + 0.5) / size - 1.0, 0.0);
            const osg::Vec3d dir = ndc * toWorld - eye;
            const osg::Vec3d top = eye + dir * ((8.0 - eye.z()) / dir.z());
            const osg::Vec3d hit = eye + dir * ((-2.0 - eye.z()) / dir.z());
            // Only rays entering through the top face and hitting the square well inside its edges.
            if (std::abs(top.x()) > 7.5 || std::abs(top.y()) > 7.5 || std::abs(hit.x()) > 5.5 || std::abs(hit.y()) > 5.5)
                continue;
            ASSERT_NEAR(img.at(x, y).r(), transmittance((top - hit).length()), 5e-4) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, 300);
}

TEST_F(OpaqueGeometry, CameraInsideTheVolumeSeesTheSquareThroughWhatIsBetween)
{
    osg::ref_ptr<VolumeScene> scene = sceneWith(flatSquare({0, 0, -4.0f}, 6.0f, osg::Vec4(1, 1, 1, 1)).get());
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    const Pixels img = render(scene.get(), 32, 32, view, osg::Matrixd::perspective(30, 1, 0.5, 50));
    // The centre ray runs from the near plane (z = 2.5) to the square (z = -4).
    EXPECT_NEAR(img.at(16, 16).r(), transmittance(6.5), 1e-3);
    EXPECT_NEAR(img.at(15, 15).r(), transmittance(6.5), 1e-3);
}

TEST_F(OpaqueGeometry, TransparentGeometryAndEmptyScenesNeedNoDepthTexture)
{
    osg::ref_ptr<osg::Node> glass = flatSquare({0, 0, 0}, 4.0f, osg::Vec4(1, 1, 1, 0.5f));
    glass->getOrCreateStateSet()->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
    glass->getOrCreateStateSet()->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
    for (osg::Node* geometry : {static_cast<osg::Node*>(nullptr), glass.get()}) {
        osg::ref_ptr<VolumeScene> scene = sceneWith(geometry);
        renderOrthoFromPlusZ(scene.get(), 16, 16, 20.0);
        EXPECT_NE(scene->compositionKeys()[0].find("ClipRay=[];"), std::string::npos) << scene->compositionKeys()[0];
        EXPECT_EQ(scene->auxiliaryTextureCount(), 3u) << "volume, TF table and occupancy grid only";
    }
    osg::ref_ptr<VolumeScene> opaque = sceneWith(flatSquare({0, 0, 0}, 4.0f, osg::Vec4(1, 1, 1, 1)).get());
    renderOrthoFromPlusZ(opaque.get(), 16, 16, 20.0);
    EXPECT_EQ(opaque->auxiliaryTextureCount(), 4u) << "plus the depth texture";
}

TEST_F(OpaqueGeometry, ClipRayForcedNullDrawsTheVolumeOverTheGeometry)
{
    osg::ref_ptr<VolumeScene> scene = sceneWith(flatSquare({0, 0, 0}, 4.0f, osg::Vec4(1, 1, 1, 1)).get());
    scene->pass.forceNull.insert("ClipRay");
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 40, 40, 20.0);
    EXPECT_NE(scene->compositionKeys()[0].find("ClipRay=[];"), std::string::npos);
    // The whole box is composited over the square.
    EXPECT_NEAR(img.at(20, 20).r(), transmittance(n), 2e-4);
}

TEST_F(OpaqueGeometry, IsosurfaceHidesThePartOfAPlaneBehindItAndLeavesItsDepth)
{
    const int size = 32;
    const double radius = 10.0;
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::Float32, {size, size, size});
    auto* v = reinterpret_cast<float*>(volume->data());
    for (int k = 0; k < size; ++k)
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                const double x = i + 0.5 - size / 2.0, y = j + 0.5 - size / 2.0, z = k + 0.5 - size / 2.0;
                v[i + size * (j + size * k)] = float(radius - std::sqrt(x * x + y * y + z * z));
            }
    volume->dirty();
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), constantTransferFunction(osg::Vec4(1, 0, 0, 1), -20, 20).get());
    node->settings.functions["RayTraversal"] = "isosurface";
    node->settings.parameters["isoValue"] = 0.0;
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(node.get());
    scene->addChild(flatSquare({0, 0, 0}, 15.0f, osg::Vec4(0, 0, 1, 1)).get());  // through the centre

    renderer(size, size).setReadDepth(true);
    const double eyeZ = 100.0, nearPlane = 50.0, farPlane = 150.0;
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, eyeZ), osg::Vec3d(), osg::Vec3d(0, 1, 0));
    const Pixels img = render(scene.get(), size, size, view, osg::Matrixd::ortho(-16, 16, -16, 16, nearPlane, farPlane));
    renderer(size, size).setReadDepth(false);
    int front = 0, plane = 0;
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            const double x = px + 0.5 - 16, y = py + 0.5 - 16, r = std::sqrt(x * x + y * y);
            const osg::Vec4& c = img.at(px, py);
            const float depth = img.depth[std::size_t(py) * size + px];
            if (r < radius - 1) {  // the sphere's front half covers the plane
                EXPECT_EQ(c.b(), 0.0f) << "plane shows through the isosurface at " << px << "," << py;
                EXPECT_GT(c.r(), 0.0f);
                const double surfaceZ = std::sqrt(radius * radius - r * r);
                EXPECT_NEAR(depth, (eyeZ - surfaceZ - nearPlane) / (farPlane - nearPlane), 0.5 / (farPlane - nearPlane));
                ++front;
            } else if (r > radius + 1 && std::abs(x) < 15 && std::abs(y) < 15) {  // the plane beside it
                EXPECT_EQ(c, osg::Vec4(0, 0, 1, 1)) << px << "," << py;
                EXPECT_NEAR(depth, (eyeZ - nearPlane) / (farPlane - nearPlane), 1e-6);
                ++plane;
            }
        }
    EXPECT_GT(front, 200);
    EXPECT_GT(plane, 200);
}

TEST_F(OpaqueGeometry, AModelUnderAScalingTransformIsLitAsAtUnitScale)
{
    // A lit sphere of radius 1 scaled 20x looks exactly like a sphere of radius 20: its normals
    // are renormalised (without, they are 20 long and the fixed-function light saturates).
    if (const char* profile = std::getenv("VOLREN_GL_PROFILE"); profile && std::string(profile) == "core")
        GTEST_SKIP() << "fixed-function lighting: compatibility contexts only";
    auto sphereScene = [](float radius, double scale) {
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(new osg::ShapeDrawable(new osg::Sphere(osg::Vec3(), radius)));
        osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(osg::Matrix::scale(scale, scale, scale));
        placed->addChild(geode.get());
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        scene->addChild(placed.get());
        osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
        light->getLight()->setPosition(osg::Vec4(0.3f, 0.4f, 1.0f, 0.0f));
        scene->addChild(light.get());
        return scene;
    };
    const Pixels scaled = renderOrthoFromPlusZ(sphereScene(1.0f, 20.0).get(), 48, 48, 50.0);
    const Pixels unit = renderOrthoFromPlusZ(sphereScene(20.0f, 1.0).get(), 48, 48, 50.0);
    float worst = 0.0f, brightest = 0.0f;
    for (std::size_t i = 0; i < unit.rgba.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, std::abs(unit.rgba[i][c] - scaled.rgba[i][c]));
            brightest = std::max(brightest, unit.rgba[i][c]);
        }
    EXPECT_GT(brightest, 0.3f) << "the sphere is lit";
    EXPECT_LE(worst, 2e-3f);
}

TEST_F(OpaqueGeometry, GeometryAddedAfterAFrameMixesInAsIfItHadBeenThereFromTheStart)
{
    // A live scene (volren view) gets a model after it has drawn: its next frame equals the
    // frame of a scene that had the model from the start.
    for (const float z : {0.0f, -5.5f}) {
        osg::ref_ptr<VolumeScene> live = sceneWith(nullptr);
        osg::ref_ptr<osg::Node> square = flatSquare({0, 0, z}, 4.0f, osg::Vec4(1, 1, 1, 1));
        renderOrthoFromPlusZ(live.get(), 40, 40, 20.0);
        live->addChild(square.get());
        const Pixels after = renderOrthoFromPlusZ(live.get(), 40, 40, 20.0);
        const Pixels fromStart = renderOrthoFromPlusZ(sceneWith(square.get()).get(), 40, 40, 20.0);
        for (std::size_t i = 0; i < after.rgba.size(); ++i)
            for (int c = 0; c < 4; ++c) ASSERT_NEAR(after.rgba[i][c], fromStart.rgba[i][c], 1e-6) << "z " << z << " pixel " << i;
        EXPECT_NEAR(after.at(20, 20).g(), transmittance(n / 2.0 - z), 2e-4);
    }
}

}  // namespace
}  // namespace volren::test
