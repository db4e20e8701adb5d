// Traversal, reconstruction and clipping behaviours against closed forms.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_model/ClipPlaneNode.h>

#include <osg/LightSource>

#include <cmath>
#include <random>

namespace volren::test {
namespace {

class ClosedForm : public RenderFixture
{
protected:
    /// A linear grey TF: colour = alpha = 1 ... colour r = window position, alpha 1.
    static osg::ref_ptr<TransferFunction> greyRamp(double lo, double hi)
    {
        osg::ref_ptr<TransferFunction> tf = new TransferFunction;
        tf->setPoint(lo, osg::Vec4(0, 0, 0, 1));
        tf->setPoint(hi, osg::Vec4(1, 1, 1, 1));
        tf->setResolution(4097);
        return tf;
    }

    /// Float volume whose voxel (i,j,k) holds f(i,j,k).
    template <typename F>
    static osg::ref_ptr<Volume> field(const osg::Vec3i& dims, F f)
    {
        osg::ref_ptr<Volume> v = new Volume;
        v->allocate(VoxelType::Float32, dims);
        auto* data = reinterpret_cast<float*>(v->data());
        for (int k = 0; k < dims.z(); ++k)
            for (int j = 0; j < dims.y(); ++j)
                for (int i = 0; i < dims.x(); ++i) data[i + dims.x() * (j + dims.y() * k)] = float(f(i, j, k));
        v->dirty();
        return v;
    }
};

TEST_F(ClosedForm, MipOfEachColumnIsItsLargestVoxel)
{
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> noise(0, 150);
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::UInt8, {8, 8, 8});
    for (std::size_t i = 0; i < volume->voxelCount(); ++i) volume->data()[i] = std::uint8_t(noise(rng));
    volume->data()[3 + 8 * (4 + 8 * 5)] = 251;  // one hot voxel
    volume->dirty();
    for (const char* reconstruction : {"nearest", "trilinear"}) {
        osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), greyRamp(0, 255).get());
        node->settings.functions["RayTraversal"] = "mip";
        node->settings.functions["Reconstruction"] = reconstruction;
        node->settings.sampleDistanceFactor = 1.0;  // samples land on voxel centres along z
        // 8x8 pixels over the 8x8 face: pixel centres are voxel centres.
        const Pixels img = renderOrthoFromPlusZ(node.get(), 8, 8, 8.0);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                double expected = 0;
                for (int z = 0; z < 8; ++z) expected = std::max(expected, volume->value(x, y, z));
                ASSERT_NEAR(img.at(x, y).r(), expected / 255.0, 2e-4) << reconstruction << " " << x << "," << y;
                ASSERT_NEAR(img.at(x, y).a(), 1.0, 1e-6);
            }
        EXPECT_NEAR(img.at(3, 4).r(), 251.0 / 255.0, 2e-4);
    }
}

TEST_F(ClosedForm, IsosurfaceOfASphereWritesItsDepthWithinHalfAVoxel)
{
    const int n = 32;
    const double radius = 10.0;  // voxel units, spacing 1
    osg::ref_ptr<Volume> volume = field({n, n, n}, [&](int i, int j, int k) {
        const double x = i + 0.5 - n / 2.0, y = j + 0.5 - n / 2.0, z = k + 0.5 - n / 2.0;
        return radius - std::sqrt(x * x + y * y + z * z);  // signed distance: > 0 inside
    });
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), greyRamp(-20, 20).get());
    node->settings.functions["RayTraversal"] = "isosurface";
    node->settings.parameters["isoValue"] = 0.0;

    renderer(32, 32).setReadDepth(true);
    const double eyeZ = 100.0, nearPlane = 50.0, farPlane = 150.0;
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, eyeZ), osg::Vec3d(), osg::Vec3d(0, 1, 0));
    const Pixels img = render(node.get(), 32, 32, view, osg::Matrixd::ortho(-16, 16, -16, 16, nearPlane, farPlane));
    renderer(32, 32).setReadDepth(false);
    ASSERT_EQ(img.depth.size(), 32u * 32u);
    int hits = 0;
    for (int py = 0; py < 32; ++py)
        for (int px = 0; px < 32; ++px) {
            const double x = px + 0.5 - 16, y = py + 0.5 - 16, r2 = x * x + y * y;
            const float depth = img.depth[std::size_t(py) * 32 + px];
            if (r2 > (radius - 1) * (radius - 1) && r2 < (radius + 1) * (radius + 1)) continue;  // rim
            if (r2 >= radius * radius) {
                EXPECT_EQ(depth, 1.0f) << "no surface at " << px << "," << py;
                continue;
            }
            const double surfaceZ = std::sqrt(radius * radius - r2);
            const double expected = (eyeZ - surfaceZ - nearPlane) / (farPlane - nearPlane);  // ortho depth
            EXPECT_NEAR(depth, expected, 0.5 / (farPlane - nearPlane)) << px << "," << py;
            EXPECT_EQ(img.at(px, py).a(), 1.0f);
            ++hits;
        }
    EXPECT_GT(hits, 200);
}

TEST_F(ClosedForm, ClipPlaneThroughTheCentreHalvesTheAreaOfASphere)
{
    const int n = 40;
    osg::ref_ptr<Volume> volume = field({n, n, n}, [&](int i, int j, int k) {
        const double x = i + 0.5 - n / 2.0, y = j + 0.5 - n / 2.0, z = k + 0.5 - n / 2.0;
        return std::sqrt(x * x + y * y + z * z) < 15.0 ? 1.0 : 0.0;
    });
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.49, osg::Vec4(1, 1, 1, 0));
    tf->setPoint(0.5, osg::Vec4(1, 1, 1, 1));
    tf->setPoint(1.0, osg::Vec4(1, 1, 1, 1));
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(volumeNode(volume.get(), tf.get()).get());
    auto area = [](const Pixels& p) {
        int n = 0;
        for (const osg::Vec4& c : p.rgba) n += c.a() > 0.5f;
        return n;
    };
    const int whole = area(renderOrthoFromPlusZ(scene.get(), 64, 64, 40.0));
    EXPECT_NEAR(whole, 3.14159 * 15 * 15 * (64.0 / 40) * (64.0 / 40), 0.03 * whole) << "disc of radius 15";
    for (const char* mode : {"ray", "position"}) {
        osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
        plane->plane.set(0.6, 0.8, 0.0, 0.0);  // through the centre, tilted in the image plane
        scene->addChild(plane.get());
        auto* node = dynamic_cast<VolumeNode*>(scene->getChild(0));
        if (std::string(mode) == "position") node->settings.functions["ClipRay"] = "null";
        const int half = area(renderOrthoFromPlusZ(scene.get(), 64, 64, 40.0));
        EXPECT_NEAR(half, whole / 2.0, 0.03 * whole) << mode;
        EXPECT_NE(scene->compositionKeys()[0].find(std::string(mode) == "ray" ? "ClipRay=[plane]" : "ClipPosition=[plane]"),
                  std::string::npos);
        scene->removeChild(plane.get());
        node->settings.functions.erase("ClipRay");
    }
}

TEST_F(ClosedForm, TricubicBSplineReproducesALinearRamp)
{
    const int n = 16;
    osg::ref_ptr<Volume> volume = field({n, 4, 4}, [](int i, int, int) { return double(i); });
    for (const char* reconstruction : {"tricubic", "trilinear"}) {
        osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), greyRamp(0, n - 1).get());
        node->settings.functions["Reconstruction"] = reconstruction;
        node->settings.functions["RayTraversal"] = "average";
        // 64 pixels across the 16 voxels; x in voxel units at pixel centre p: (p + 0.5) / 4.
        const Pixels img = renderOrthoFromPlusZ(node.get(), 64, 16, 4.0);  // 16 x 4 world units
        for (int px = 12; px < 52; ++px) {  // two voxels away from the borders (clamped there)
            const double value = (px + 0.5) / 4.0 - 0.5;  // texel centres at i + 0.5
            EXPECT_NEAR(img.at(px, 8).r(), value / (n - 1), 2e-4) << reconstruction << " pixel " << px;
        }
    }
}

TEST_F(ClosedForm, SurfaceLightingMixesUnlitAndLitByTheGradientMagnitude)
{
    // lighting_surface = mix(unlit, lit, w) with w = 1 - exp(-|g| / (0.05 G)), G the gradient of a
    // jump across the TF window within one voxel. Values rise by 10 per voxel along x over the
    // window 0..255: |g| = 10, G = 255, w = 1 - exp(-10 / 12.75). One colour and opacity for every
    // value, so every sample of a ray has the same colour: the pixel mixes as its samples do.
    // A homogeneous volume (zero gradient) stays exactly unlit.
    osg::ref_ptr<Volume> ramp = new Volume;
    ramp->allocate(VoxelType::UInt8, {16, 8, 8});
    for (std::size_t i = 0; i < ramp->voxelCount(); ++i) ramp->data()[i] = std::uint8_t(20 + 10 * (i % 16));
    ramp->dirty();
    const osg::Vec4 albedo(0.8f, 0.5f, 0.25f, 0.1f);
    auto pixel = [&](Volume* volume, const char* shading) {
        auto node = volumeNode(volume, constantTransferFunction(albedo).get());
        node->settings.functions["Shading"] = shading;
        node->settings.earlyTerminationThreshold = 1.0;
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        scene->addChild(node.get());
        osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
        light->getLight()->setPosition(osg::Vec4(-1, 0, 1, 0));
        scene->addChild(light.get());
        return renderOrthoFromPlusZ(scene.get(), 16, 16, 16.0).at(8, 8);
    };
    const double w = -std::expm1(-10.0 / (0.05 * 255.0));
    const osg::Vec4 unlit = pixel(ramp.get(), "null"), lit = pixel(ramp.get(), "lighting");
    const osg::Vec4 surface = pixel(ramp.get(), "lighting_surface");
    ASSERT_GT(std::abs(lit.r() - unlit.r()), 0.02f) << "the light must change the colour for the test to see w";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(surface[c], (1.0 - w) * unlit[c] + w * lit[c], 2e-3) << "channel " << c;
    EXPECT_NEAR(surface.a(), lit.a(), 1e-6);

    osg::ref_ptr<Volume> flat = constantVolume(VoxelType::UInt8, {16, 8, 8}, 100);
    const osg::Vec4 flatSurface = pixel(flat.get(), "lighting_surface"), flatUnlit = pixel(flat.get(), "null");
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(flatSurface[c], flatUnlit[c], 1e-6) << "zero gradient: unlit, channel " << c;
}

}  // namespace
}  // namespace volren::test
