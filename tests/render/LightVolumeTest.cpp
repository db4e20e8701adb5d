// The Shadowing implementations that build auxiliary volumes on the GPU, against closed forms
// and against shadow rays: light_volume, and cone / cone_ao (cone tracing).
//
// Shadowing/light_volume. In a homogeneous block lit
// along an axis, the build is exact at the light volume's texel centres: a texel d voxels below
// the lit face holds exp(-sigma * d) (the path to the face is integrated exactly, the slices'
// bilinear gathers read a constant slice). A sample between texel centres reads the trilinear
// mix of its two neighbours (clamped at the ends), stored in half floats; that is the expected
// shadow of each view-ray segment, and shadow rays give the continuous exp(-sigma * s).
#include "LitBlock.h"
#include "TestData.h"

#include <volume_model/ClipPlaneNode.h>
#include <volume_model/DefaultScene.h>
#include <volume_reference/ReferenceSetup.h>

#include <cmath>
#include <functional>

namespace volren::test {
namespace {

class LightVolume : public LitBlock
{
protected:
    /// What a light volume of `n` texels along z reads at `depth` voxels below the lit face of
    /// the block when its texels hold exp(-sigma * (depth of their centre - `cut`)), or 1 above
    /// `cut` (material above it clipped away): the linear mix of the two nearest centres.
    static double interpolated(double depth, int n, double cut = 0.0)
    {
        const double texel = double(depthVoxels) / n;
        auto stored = [&](int k) {  // texel k counted from the lit face
            const double d = (k + 0.5) * texel;
            return d <= cut ? 1.0 : std::exp(-sigma * (d - cut));
        };
        const double u = std::clamp(depth / texel - 0.5, 0.0, n - 1.0);
        const int k = std::min(int(u), n - 2);
        return stored(k) + (stored(k + 1) - stored(k)) * (u - k);
    }
};

TEST_F(LightVolume, AHomogeneousBlockHoldsExpMinusSigmaDAtItsTexelCentres)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    const osg::Vec4 unlit = renderOrthoFromPlusZ(lit(block.get(), tf.get(), "null").get(), 8, 8, 32.0).at(4, 4);
    ASSERT_GT(unlit.r(), 0.1f);
    const double exact = expectedRatio(0, [](int i) { return std::exp(-sigma * (i + 0.5) * step); });
    for (const double scale : {1.0, 0.5, 0.25}) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), "light_volume", scale);
        const osg::Vec4 shadowed = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
        ASSERT_NE(scene->compositionKeys()[0].find("Shadowing=light_volume"), std::string::npos) << scene->compositionKeys()[0];
        const int n = int(std::lround(depthVoxels * scale));
        const double ratio = expectedRatio(0, [&](int i) { return interpolated((i + 0.5) * step, n); });
        // Half floats hold the transmittance to 2^-11 of itself, and each slice multiplies the
        // rounded value of the one before: n roundings of up to 2^-12 relative (n = 16: 3.9e-3
        // at worst; measured 1.2e-3).
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(shadowed[c] / unlit[c], ratio, 2.5e-3) << "scale " << scale << " channel " << c;
        EXPECT_NEAR(shadowed.a(), unlit.a(), 1e-6) << "shadows change light, not coverage";
        // Against the continuous exp(-sigma s) of shadow rays: linear interpolation of the
        // exponential over texels of 1, 2 and 4 voxels (and the clamped half texels at the ends).
        EXPECT_NEAR(ratio, exact, 0.02 / scale);
        const std::vector<BuiltVolumeStatistics> stats = scene->builtVolumeStatistics();
        ASSERT_EQ(stats.size(), 1u);
        EXPECT_EQ(stats[0].dims, osg::Vec3i(n, n, n));
        EXPECT_EQ(stats[0].channels, 1);
        EXPECT_EQ(stats[0].bytes, std::size_t(n) * n * n * 2) << "R16F: 2 bytes per texel";
        EXPECT_EQ(stats[0].builds, 1u);
    }
}

TEST_F(LightVolume, ClippedAwayMaterialCastsNoShadow)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    auto clipped = [&](const char* shadowing) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), shadowing);
        osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
        plane->plane.set(0.0, 0.0, -1.0, 0.0);  // keeps z <= 0: the half nearest the light is gone
        scene->addChild(plane.get());
        return scene;
    };
    const osg::Vec4 unlit = renderOrthoFromPlusZ(clipped("null").get(), 8, 8, 32.0).at(4, 4);
    const int half = int(depthVoxels / step) / 2;
    // The build integrates each path at the view step: the plane cuts the texels' paths to within
    // a step, so a texel d below the face holds exp(-sigma (d - 8)) below the cut.
    const double ratio = expectedRatio(half, [&](int i) { return interpolated((i + 0.5) * step, depthVoxels, 8.0); });
    osg::ref_ptr<VolumeScene> scene = clipped("light_volume");
    const osg::Vec4 shadowed = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
    EXPECT_NE(scene->compositionKeys()[0].find("ClipPosition=[plane]"), std::string::npos) << scene->compositionKeys()[0];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(shadowed[c] / unlit[c], ratio, 2e-3) << "channel " << c;
    // With the clipped half casting its shadow the ratio would be exp(-8 sigma) times lower.
    EXPECT_GT(ratio, 1.5 * ratio * std::exp(-sigma * 8.0));
}

/// A block of density 60 around a sphere of density 200 (16x24x20, anisotropic spacing), whose
/// shadow falls across the block for oblique lights.
osg::ref_ptr<Volume> sphereInBlock()
{
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::UInt8, {16, 24, 20});
    volume->setSpacing({1.0, 1.0, 1.25});
    for (int z = 0; z < 20; ++z)
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 16; ++x) {
                const double r = std::hypot(x - 9.0, y - 14.0, 1.25 * (z - 12.0));
                volume->data()[(std::size_t(z) * 24 + y) * 16 + x] = r < 6.0 ? 200 : 60;
            }
    volume->dirty();
    return volume;
}

double rmse(const Pixels& a, const Pixels& b)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        for (int c = 0; c < 3; ++c) sum += double(a.rgba[i][c] - b.rgba[i][c]) * (a.rgba[i][c] - b.rgba[i][c]);
    return std::sqrt(sum / (3.0 * a.rgba.size()));
}

TEST_F(LightVolume, ConvergesToShadowRaysAsItsResolutionGrows)
{
    osg::ref_ptr<Volume> volume = sphereInBlock();
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {60, {0.9f, 0.8f, 0.6f, 0.05f}}, {200, {0.4f, 0.7f, 1.0f, 0.5f}}, {255, {1, 1, 1, 0.5f}}}, 0, 255);
    for (const std::vector<osg::Vec4>& lights : std::vector<std::vector<osg::Vec4>>{
             {{1, 0.6f, 0.8f, 0}}, {{-12, 10, 20, 1}}, {{0, 0, 1, 0}, {-1, 0, 0, 0}}}) {
        const Pixels rays = renderOrthoFromPlusZ(lit(volume.get(), tf.get(), "ray", 1.0, lights).get(), 40, 40, 36.0);
        const Pixels none = renderOrthoFromPlusZ(lit(volume.get(), tf.get(), "null", 1.0, lights).get(), 40, 40, 36.0);
        std::vector<double> errors;
        for (const double scale : {0.25, 0.5, 1.0})
            errors.push_back(rmse(renderOrthoFromPlusZ(lit(volume.get(), tf.get(), "light_volume", scale, lights).get(), 40, 40, 36.0), rays));
        const double shadowEffect = rmse(none, rays);
        ::testing::Message lightText;
        for (const osg::Vec4& l : lights) lightText << l.x() << "," << l.y() << "," << l.z() << "," << l.w() << " ";
        EXPECT_GT(shadowEffect, 0.02) << "the shadows change the image: " << lightText;
        EXPECT_LT(errors[1], errors[0]) << lightText;
        EXPECT_LT(errors[2], errors[1]) << lightText;
        EXPECT_LT(errors[2], 0.1 * shadowEffect) << "within a tenth of what shadows change: " << lightText;
        std::printf("lights %s: shadow effect %.4f, light volume RMSE vs rays at 1/4, 1/2, 1: %.5f %.5f %.5f\n",
                    lightText.GetString().c_str(), shadowEffect, errors[0], errors[1], errors[2]);
    }
}

TEST_F(LightVolume, NoNaNForAxisDiagonalAndInsideLightsOrZeroGradients)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    const std::vector<osg::Vec4> lights = {{1, 0, 0, 0}, {0, -1, 0, 0}, {1, 1, 1, 0},  {-1, 1, -1, 0},
                                           {0, 0, 0, 1}, {3, -2, 5, 1}, {0, 0, 100, 1}, {8, 8, 8, 1}};
    for (const osg::Vec4& light : lights) {
        const Pixels img = renderOrthoFromPlusZ(lit(block.get(), tf.get(), "light_volume", 0.5, {light}).get(), 16, 16, 32.0);
        for (const osg::Vec4& p : img.rgba)
            for (int c = 0; c < 4; ++c)
                ASSERT_TRUE(std::isfinite(p[c]) && p[c] >= 0.0f && p[c] <= 1.0f)
                    << "light " << light.x() << "," << light.y() << "," << light.z() << "," << light.w();
    }
    // A point light at the centre: the texels around it hold exp(-sigma * distance), so the
    // centre pixel matches shadow rays closely.
    const std::vector<osg::Vec4> centre = {{0, 0, 0, 1}};
    const osg::Vec4 rays = renderOrthoFromPlusZ(lit(block.get(), tf.get(), "ray", 1.0, centre).get(), 8, 8, 32.0).at(4, 4);
    const osg::Vec4 volume = renderOrthoFromPlusZ(lit(block.get(), tf.get(), "light_volume", 1.0, centre).get(), 8, 8, 32.0).at(4, 4);
    ASSERT_GT(rays.r(), 0.0f);
    EXPECT_NEAR(volume.r() / rays.r(), 1.0, 0.03);
}

TEST_F(LightVolume, IsRebuiltOnlyWhenTheLightTheTransferFunctionOrAClipChanges)
{
    osg::ref_ptr<Volume> volume = sphereInBlock();
    osg::ref_ptr<TransferFunction> tf = transferFunction({{0, {0, 0, 0, 0}}, {60, {0.9f, 0.8f, 0.6f, 0.05f}}, {255, {1, 1, 1, 0.5f}}}, 0, 255);
    osg::ref_ptr<VolumeScene> scene = lit(volume.get(), tf.get(), "light_volume", 0.5, {{1, 0.6f, 0.8f, 0}});
    auto builds = [&] { return scene->builtVolumeStatistics().at(0).builds; };
    const osg::Matrixd ortho = osg::Matrixd::ortho(-20, 20, -20, 20, 1, 200);
    const osg::Matrixd top = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 60), osg::Vec3d(), osg::Vec3d(0, 1, 0));
    const osg::Matrixd oblique = osg::Matrixd::lookAt(osg::Vec3d(60, 10, 5), osg::Vec3d(), osg::Vec3d(0, 0, 1));
    render(scene.get(), 16, 16, top, ortho);
    EXPECT_EQ(builds(), 1u);
    // The light is fixed in the scene: another view reads the same light volume.
    const Pixels side = render(scene.get(), 16, 16, oblique, ortho);
    EXPECT_EQ(builds(), 1u) << "a camera move rebuilds nothing";
    tf->setPoint(255, {1, 1, 1, 0.4f});
    render(scene.get(), 16, 16, oblique, ortho);
    EXPECT_EQ(builds(), 2u) << "a TF edit rebuilds";
    auto* source = dynamic_cast<osg::LightSource*>(scene->getChild(1));
    source->getLight()->setPosition({-1, 0.6f, 0.8f, 0});
    const Pixels moved = render(scene.get(), 16, 16, oblique, ortho);
    EXPECT_EQ(builds(), 3u) << "a light move rebuilds";
    EXPECT_GT(rmse(side, moved), 1e-3) << "and the shadows move";
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(1.0, 0.0, 0.0, 0.0);
    scene->addChild(plane.get());
    render(scene.get(), 16, 16, oblique, ortho);
    EXPECT_EQ(builds(), 4u) << "a clip shape rebuilds";
    plane->plane.set(1.0, 0.0, 0.0, 2.0);
    render(scene.get(), 16, 16, oblique, ortho);
    EXPECT_EQ(builds(), 5u) << "moving it rebuilds";
    render(scene.get(), 16, 16, top, ortho);
    EXPECT_EQ(builds(), 5u);
}


/// The optical depth, in units of sigma, from the front face of the block down to `depth`
/// voxels through the opacity chain's finest level: sigma below half a voxel, falling linearly
/// to sigma/2 at the face (its texels blend with the zero border there).
double chainDepth(double depth)
{
    // The march from the sample upwards in steps of `step`, the last one cut at the face; each
    // sampled at its midpoint (as the shader does).
    auto field = [](double d) { return d >= 0.5 ? 1.0 : 0.5 + d; };
    double total = 0.0;
    for (double t = 0.0; t < depth - 1e-12;) {
        const double h = std::min(LitBlock::step, depth - t);
        total += field(depth - (t + 0.5 * h)) * h;
        t += h;
    }
    return total;
}

TEST_F(LightVolume, LightsFiveToEightInTheSecondLayerShadowAsEachAloneDoes)
{
    // Six lights (the last two in the light volume's second layer) light the sphere as the sum of
    // the six lit alone: Lambert light adds up, and each channel is built and read as a light
    // volume of its own would be. Dim lights keep every sum below 1.
    osg::ref_ptr<Volume> volume = sphereInBlock();
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {60, {0.9f, 0.8f, 0.6f, 0.05f}}, {200, {0.4f, 0.7f, 1.0f, 0.5f}}, {255, {1, 1, 1, 0.5f}}}, 0, 255);
    const std::vector<osg::Vec4> lights = {{0, 0, 1, 0},  {1, 0, 0, 0},      {0, 1, 0, 0},
                                           {0, -1, 1, 0}, {1, 0.6f, 0.8f, 0}, {-12, 10, 20, 1}};
    auto image = [&](const std::vector<osg::Vec4>& which) {
        osg::ref_ptr<VolumeScene> scene = lit(volume.get(), tf.get(), "light_volume", 1.0, which);
        for (unsigned int i = 1; i < scene->getNumChildren(); ++i)
            dynamic_cast<osg::LightSource*>(scene->getChild(i))->getLight()->setDiffuse({0.15f, 0.15f, 0.15f, 1});
        const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 36.0);
        if (which.size() > 4) {
            const std::vector<BuiltVolumeStatistics> stats = scene->builtVolumeStatistics();
            EXPECT_EQ(stats.at(0).dims, osg::Vec3i(16, 24, 40)) << "two layers of the volume's 16x24x20";
        }
        return img;
    };
    const Pixels all = image(lights);
    std::vector<Pixels> alone;
    for (const osg::Vec4& l : lights) alone.push_back(image({l}));
    const Pixels unshadowedLastTwo = [&] {
        osg::ref_ptr<VolumeScene> scene = lit(volume.get(), tf.get(), "null", 1.0, {lights[4], lights[5]});
        for (unsigned int i = 1; i < scene->getNumChildren(); ++i)
            dynamic_cast<osg::LightSource*>(scene->getChild(i))->getLight()->setDiffuse({0.15f, 0.15f, 0.15f, 1});
        return renderOrthoFromPlusZ(scene.get(), 32, 32, 36.0);
    }();
    double largest = 0.0, shadowOfLastTwo = 0.0;
    for (std::size_t p = 0; p < all.rgba.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0;
            for (const Pixels& one : alone) sum += one.rgba[p][c];
            ASSERT_LT(sum, 0.95) << "no clamping";
            largest = std::max(largest, std::abs(all.rgba[p][c] - sum));
            shadowOfLastTwo = std::max(shadowOfLastTwo, std::abs(double(unshadowedLastTwo.rgba[p][c]) - alone[4].rgba[p][c] -
                                                                 alone[5].rgba[p][c]));
        }
    EXPECT_GT(shadowOfLastTwo, 0.01) << "lights 5 and 6 cast shadows worth testing";
    EXPECT_LT(largest, 2e-4);
}

TEST_F(LightVolume, ANarrowConeIsAShadowRayThroughTheExtinctionField)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    const osg::Vec4 unlit = renderOrthoFromPlusZ(lit(block.get(), tf.get(), "null").get(), 8, 8, 32.0).at(4, 4);
    for (const char* method : {"cone", "cone_ao"}) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), method);
        VolumeNode* node = findVolumeNodes(*scene)[0];
        node->settings.parameters["coneAngle"] = 0.5;  // one voxel wide for 115 voxels: level 0 all the way
        node->settings.parameters["coneStart"] = 0.0;
        node->settings.parameters["coneStepGrowth"] = 0.5;  // steps of half the one-voxel diameter: the shadow step
        node->settings.parameters["ambient"] = 0.0;    // no ambient term for cone_ao's occlusion to scale
        const osg::Vec4 shadowed = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
        ASSERT_NE(scene->compositionKeys()[0].find(std::string("Shadowing=") + method), std::string::npos);
        // Steps of half a voxel from the sample: midpoints of a field linear within each.
        const double ratio = expectedRatio(0, [](int i) { return std::exp(-sigma * chainDepth((i + 0.5) * step)); });
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(shadowed[c] / unlit[c], ratio, 1e-3) << method << " channel " << c;
        const std::vector<BuiltVolumeStatistics> stats = scene->builtVolumeStatistics();
        ASSERT_EQ(stats.size(), 1u);
        EXPECT_EQ(stats[0].kind, "opacity mip chain");
        EXPECT_EQ(stats[0].dims, osg::Vec3i(depthVoxels, depthVoxels, depthVoxels));
        // Half floats, every level: 16^3 + 8^3 + ... + 1 texels of 2 bytes.
        EXPECT_EQ(stats[0].bytes, std::size_t(2 * (4096 + 512 + 64 + 8 + 1)));
    }
}

TEST_F(LightVolume, AmbientOcclusionDeepInAHomogeneousMediumIsExpMinusSigmaTimesItsReach)
{
    // A 64^3 block as opaque everywhere, emitting only in the layer 20-21 voxels below the face
    // the viewer (and the normal) look at. Lit by ambient light only (a black light), the layer
    // shows the ambient term times its occlusion; every cone over its hemisphere (8 voxels long,
    // at most 4.6 wide) samples levels whose texels lie inside the block, where they average a
    // constant: the occlusion is exp(-sigma (8 - 0.5)) (cones start half a voxel out).
    const int n = 64;
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::UInt8, {n, n, n});
    for (int z = 0; z < n; ++z)
        std::fill_n(volume->data() + std::size_t(z) * n * n, std::size_t(n) * n, z == n - 21 ? 200 : 100);
    volume->dirty();
    // Black up to 150 (the lookup table's entries near 100 hold no colour at all), white at 200.
    osg::ref_ptr<TransferFunction> tf = transferFunction({{150, {0, 0, 0, float(alpha)}}, {200, {1, 1, 1, float(alpha)}}}, 0, 255);
    auto image = [&](const char* method) {
        osg::ref_ptr<VolumeScene> scene = lit(volume.get(), tf.get(), method);
        VolumeNode* node = findVolumeNodes(*scene)[0];
        node->settings.parameters["ambient"] = 0.5;
        dynamic_cast<osg::LightSource*>(scene->getChild(1))->getLight()->setDiffuse({0, 0, 0, 1});
        return renderOrthoFromPlusZ(scene.get(), 8, 8, 128.0).at(4, 4);
    };
    const osg::Vec4 open = image("cone"), occluded = image("cone_ao");
    ASSERT_GT(open.r(), 1e-4f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(occluded[c] / open[c], std::exp(-sigma * 7.5), 2e-3) << "channel " << c;
}

TEST_F(LightVolume, ConeTracingFollowsShadowRaysAndRebuildsOnlyForTheTransferFunction)
{
    osg::ref_ptr<Volume> volume = sphereInBlock();
    osg::ref_ptr<TransferFunction> tf =
        transferFunction({{0, {0, 0, 0, 0}}, {60, {0.9f, 0.8f, 0.6f, 0.05f}}, {200, {0.4f, 0.7f, 1.0f, 0.5f}}, {255, {1, 1, 1, 0.5f}}}, 0, 255);
    const std::vector<osg::Vec4> lights = {{1, 0.6f, 0.8f, 0}};
    const Pixels rays = renderOrthoFromPlusZ(lit(volume.get(), tf.get(), "ray", 1.0, lights).get(), 40, 40, 36.0);
    const Pixels none = renderOrthoFromPlusZ(lit(volume.get(), tf.get(), "null", 1.0, lights).get(), 40, 40, 36.0);
    std::vector<double> errors;
    for (const double angle : {30.0, 10.0, 1.0}) {
        osg::ref_ptr<VolumeScene> scene = lit(volume.get(), tf.get(), "cone", 1.0, lights);
        findVolumeNodes(*scene)[0]->settings.parameters["coneAngle"] = double(angle);
        findVolumeNodes(*scene)[0]->settings.parameters["coneStart"] = 0.0;
        errors.push_back(rmse(renderOrthoFromPlusZ(scene.get(), 40, 40, 36.0), rays));
    }
    std::printf("shadow effect %.4f, cone RMSE vs rays at 30, 10, 1 degrees: %.5f %.5f %.5f\n", rmse(none, rays), errors[0],
                errors[1], errors[2]);
    EXPECT_LT(errors[1], errors[0]);
    EXPECT_LE(errors[2], errors[1]);
    EXPECT_LT(errors[2], 0.25 * rmse(none, rays)) << "a narrow cone differs from a ray by the interpolated extinction only";

    osg::ref_ptr<VolumeScene> scene = lit(volume.get(), tf.get(), "cone_ao", 1.0, lights);
    auto builds = [&] { return scene->builtVolumeStatistics().at(0).builds; };
    for (const osg::Vec4& light : std::vector<osg::Vec4>{{1, 0.6f, 0.8f, 0}, {-1, 0, 0, 0}, {0, 0, 30, 1}}) {
        dynamic_cast<osg::LightSource*>(scene->getChild(1))->getLight()->setPosition(light);
        const Pixels img = renderOrthoFromPlusZ(scene.get(), 16, 16, 36.0);
        for (const osg::Vec4& p : img.rgba)
            for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(p[c]) && p[c] >= 0.0f && p[c] <= 1.0f);
    }
    EXPECT_EQ(builds(), 1u) << "the chain does not depend on the lights";
    tf->setPoint(255, {1, 1, 1, 0.4f});
    renderOrthoFromPlusZ(scene.get(), 16, 16, 36.0);
    EXPECT_EQ(builds(), 2u) << "a TF edit rebuilds it";
}

TEST_F(LightVolume, TheReferenceMeasuresEachShadowingAgainstWhatItApproximates)
{
    // Every method approximates exact shadows; cone_ao also the ambient occlusion. The reference
    // setup reads this from the implementations' traits, the bench's truth keys from it.
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {8, 8, 8}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(1, 1, 1, 0.1f));
    const std::map<std::string, std::pair<ReferenceScene::Shadows, bool>> expected = {
        {"null", {ReferenceScene::Shadows::None, false}},  {"ray", {ReferenceScene::Shadows::Exact, false}},
        {"light_volume", {ReferenceScene::Shadows::Exact, false}}, {"cone", {ReferenceScene::Shadows::Exact, false}},
        {"cone_ao", {ReferenceScene::Shadows::Exact, true}}};
    for (const auto& [method, truth] : expected) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), method.c_str());
        const ReferenceScene content = referenceScene(*scene);
        ASSERT_EQ(content.volumes.size(), 1u);
        ASSERT_TRUE(content.volumes[0].shadows.has_value()) << method;
        EXPECT_EQ(*content.volumes[0].shadows, truth.first) << method;
        EXPECT_EQ(content.volumes[0].occlusion, truth.second) << method;
    }
}

}  // namespace
}  // namespace volren::test
