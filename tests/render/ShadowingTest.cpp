// Shadowing/ray against closed forms. A homogeneous block lit by a directional light from the
// viewer (a headlight): every sample's normal is the view direction (zero gradient), so
// Lambert gives 1 and, with no ambient, a sample's emission is K * c * T_light. The shadow ray
// to the light runs back along the view ray, so T_light = exp(-sigma * s) for a sample s deep:
// the image with shadows is the image without, each segment weighted by that factor.
#include "LitBlock.h"
#include "ReferenceComparison.h"
#include "TestData.h"

#include <volume_model/ClipPlaneNode.h>
#include <volume_model/DefaultScene.h>
#include <volume_reference/ReferenceSetup.h>
#include <volume_model/ReferenceModel.h>
#include <volume_renderer/LoopBudget.h>

#include <cmath>

namespace volren::test {
namespace {

class Shadowing : public LitBlock
{
};

TEST_F(Shadowing, AHomogeneousBlockLitFromTheViewerShadowsItselfByExpMinusSigmaS)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    const osg::Vec4 unlit = renderOrthoFromPlusZ(lit(block.get(), tf.get(), "null").get(), 8, 8, 32.0).at(4, 4);
    osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), "ray");
    const osg::Vec4 shadowed = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
    EXPECT_NE(scene->compositionKeys()[0].find("Shadowing=ray"), std::string::npos);
    const double sigma = -std::log1p(-alpha);
    const double ratio = expectedRatio(0, [&](int i) { return std::exp(-sigma * (i + 0.5) * step); });
    ASSERT_GT(unlit.r(), 0.1f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(shadowed[c] / unlit[c], ratio, 2e-4) << "channel " << c;
    EXPECT_NEAR(shadowed.a(), unlit.a(), 1e-6) << "shadows change light, not coverage";
    // The continuous limit, (1 - exp(-2 sigma D)) / 2 over 1 - exp(-sigma D), within the step's error.
    const double D = depthVoxels;
    EXPECT_NEAR(ratio, 0.5 * -std::expm1(-2 * sigma * D) / -std::expm1(-sigma * D), 2e-3);
    // A shorter shadow step changes nothing in a homogeneous medium (midpoint segments are exact).
    scene = lit(block.get(), tf.get(), "ray");
    findVolumeNodes(*scene)[0]->settings.parameters["shadowStepFactor"] = 0.13;
    EXPECT_NEAR(renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4).r() / unlit.r(), ratio, 2e-4);
}

TEST_F(Shadowing, ADarkSlabBetweenTheLightAndTheBlockLetsExpMinusSigmaDThrough)
{
    // The front 4 voxels (k >= 12, nearest the light) hold 50: black but as opaque as the rest
    // (100, coloured), so sigma is the same everywhere and only the colour marks the slab.
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels});
    for (std::size_t i = 0; i < volume->voxelCount(); ++i) volume->data()[i] = i / (depthVoxels * depthVoxels) >= 12 ? 50 : 100;
    volume->dirty();
    osg::ref_ptr<TransferFunction> tf = transferFunction({{50, {0, 0, 0, float(alpha)}}, {100, {0.9f, 0.6f, 0.3f, float(alpha)}}}, 0, 255);
    const osg::Vec4 unlit = renderOrthoFromPlusZ(lit(volume.get(), tf.get(), "null").get(), 8, 8, 32.0).at(4, 4);
    const osg::Vec4 shadowed = renderOrthoFromPlusZ(lit(volume.get(), tf.get(), "ray").get(), 8, 8, 32.0).at(4, 4);
    // Segment i's midpoint is (i + 0.5) * step below the front face (z = 16 in voxel units); its
    // colour weight is the trilinear value's place between 50 and 100 (voxel centres at k + 0.5).
    auto weight = [](int i) {
        const double z = depthVoxels - (i + 0.5) * step;  // voxel coordinate
        const double k = std::clamp(z - 0.5, 0.0, depthVoxels - 1.0);
        const double front = std::clamp(k - 11.0, 0.0, 1.0);  // 0 at voxel 11's centre, 1 at 12's
        return 1.0 - front;
    };
    const double sigma = -std::log1p(-alpha);
    const double ratio = expectedRatio(0, [&](int i) { return std::exp(-sigma * (i + 0.5) * step); }, weight);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(shadowed[c] / unlit[c], ratio, 5e-4) << "channel " << c;
    // The block behind the slab receives exp(-sigma * 4) of the light at its front: the ratio is
    // below that (deeper samples receive less).
    EXPECT_LT(ratio, std::exp(-sigma * 4.0));
}

TEST_F(Shadowing, ClippedAwayMaterialCastsNoShadow)
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
    const double sigma = -std::log1p(-alpha);
    const int half = int(depthVoxels / step) / 2;
    const double ratio = expectedRatio(half, [&](int i) { return std::exp(-sigma * (i - half + 0.5) * step); });
    // Shadow samples are clipped one by one, so the plane is found to within a shadow step: a
    // fine step gives the exact ratio, the default one is within sigma * step of it.
    for (const double factor : {0.02, 1.0}) {
        osg::ref_ptr<VolumeScene> scene = clipped("ray");
        findVolumeNodes(*scene)[0]->settings.parameters["shadowStepFactor"] = double(factor);
        const osg::Vec4 shadowed = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
        EXPECT_NE(scene->compositionKeys()[0].find("ClipPosition=[plane]"), std::string::npos)
            << "shadow rays need the plane per sample: " << scene->compositionKeys()[0];
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(shadowed[c] / unlit[c], ratio, factor < 1.0 ? 1e-3 : sigma * step * ratio) << "step factor " << factor;
    }
    // Without the clip, the clipped half would shadow too: far darker.
    EXPECT_LT(ratio * std::exp(-sigma * depthVoxels / 2.0), ratio - 0.3);
}

TEST_F(Shadowing, AFineViewStepKeepsItsShadowsWithinTheDriversLoopLimit)
{
    // llvmpipe ends all loops of a pixel after 65,535 iterations together. At 1/200 voxel per view
    // sample (5,543 per ray through the block) shadow marches at the same step would need 30
    // million: the shadow step is lengthened to fit, which a homogeneous block does not notice
    // (midpoint segments are exact), so the image is the continuous closed form. (Before, the view
    // ray stopped after a dozen samples: coverage 0.03 of 0.74, with no message.) A driver
    // without such a limit keeps the step, and the same holds.
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    auto fine = [&](const char* shadowing, double factor) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), shadowing);
        findVolumeNodes(*scene)[0]->settings.sampleDistanceFactor = factor;
        return scene;
    };
    const osg::Vec4 unlit = renderOrthoFromPlusZ(fine("null", 0.005).get(), 8, 8, 32.0).at(4, 4);
    osg::ref_ptr<VolumeScene> scene = fine("ray", 0.005);
    const osg::Vec4 shadowed = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
    EXPECT_TRUE(scene->drawErrors().empty()) << scene->drawErrors().front();
    const double D = depthVoxels;
    EXPECT_NEAR(unlit.a(), -std::expm1(-sigma * D), 2e-3);
    EXPECT_NEAR(shadowed.a(), unlit.a(), 1e-5) << "shadows change light, not coverage";
    const double continuous = 0.5 * -std::expm1(-2 * sigma * D) / -std::expm1(-sigma * D);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(shadowed[c] / unlit[c], continuous, 2e-3) << "channel " << c;

    // A view ray that alone would pass the limit (138,000 samples at 1/5000 voxel) is refused
    // with the reason, not cut short; without a known limit it is drawn.
    scene = fine("null", 0.0002);
    const osg::Vec4 refused = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
    if (loopIterationLimit() == 0) {
        EXPECT_NEAR(refused.a(), unlit.a(), 2e-3);
    } else {
        ASSERT_EQ(scene->drawErrors().size(), 1u);
        EXPECT_NE(scene->drawErrors()[0].find("ends a pixel's loops after 65535 iterations"), std::string::npos)
            << scene->drawErrors()[0];
        EXPECT_EQ(refused.a(), 0.0f);
    }
}

TEST_F(Shadowing, NoNaNForAxisDiagonalAndInsideLightsOrZeroGradients)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    const std::vector<osg::Vec4> lights = {{1, 0, 0, 0},  {0, -1, 0, 0},  {1, 1, 1, 0},      {-1, 1, -1, 0},
                                           {0, 0, 0, 1},  {3, -2, 5, 1},  {0, 0, 100, 1},   {8, 8, 8, 1}};
    for (const osg::Vec4& light : lights) {
        const Pixels img = renderOrthoFromPlusZ(lit(block.get(), tf.get(), "ray", 1.0, {light}).get(), 16, 16, 32.0);
        for (const osg::Vec4& p : img.rgba)
            for (int c = 0; c < 4; ++c)
                ASSERT_TRUE(std::isfinite(p[c]) && p[c] >= 0.0f && p[c] <= 1.0f)
                    << "light " << light.x() << "," << light.y() << "," << light.z() << "," << light.w();
    }
    // A point light at the block's centre: the samples above it receive exp(-sigma * distance).
    const osg::Vec4 inside = renderOrthoFromPlusZ(lit(block.get(), tf.get(), "ray", 1.0, {{0, 0, 0, 1}}).get(), 8, 8, 32.0).at(4, 4);
    EXPECT_GT(inside.r(), 0.0f);
}

TEST_F(Shadowing, HenyeyGreensteinScalesEachLightByThePhaseFunction)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    auto pixel = [&](const char* illumination, double g, const osg::Vec4& light) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), "ray", 1.0, {light});
        VolumeNode* node = findVolumeNodes(*scene)[0];
        node->settings.functions["Illumination"] = illumination;
        node->settings.parameters["anisotropy"] = double(g);
        return renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
    };
    // g = 0 is isotropic: the albedo times the light, as Lambert with the normal towards the light.
    const osg::Vec4 headlight(0, 0, 1, 0);
    const osg::Vec4 lambert = pixel("lambert", 0.0, headlight), isotropic = pixel("henyey_greenstein", 0.0, headlight);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(isotropic[c], lambert[c], 1e-6) << "channel " << c;
    // Light from the viewer scatters back through 180 degrees: (1 - g) / (1 + g)^2 of it.
    for (double g : {0.5, -0.5, 0.9}) {
        const osg::Vec4 p = pixel("henyey_greenstein", g, headlight);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c] / isotropic[c], (1 - g) / ((1 + g) * (1 + g)), 1e-4) << "g " << g;
        EXPECT_NEAR(p.a(), isotropic.a(), 1e-6);
    }
    // Light from the side (along -x, through no more medium than from +z: a cube) scatters through
    // 90 degrees: (1 - g^2) / (1 + g^2)^1.5, against the same side light at g = 0.
    const osg::Vec4 side(-1, 0, 0, 0);
    const osg::Vec4 sideIsotropic = pixel("henyey_greenstein", 0.0, side), sideForward = pixel("henyey_greenstein", 0.6, side);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sideForward[c] / sideIsotropic[c], (1 - 0.36) / std::pow(1 + 0.36, 1.5), 1e-4) << "channel " << c;
}

TEST_F(Shadowing, HenyeyGreensteinMatchesItsReferenceModelForwardAndBackward)
{
    // The reference's own phase function (ReferenceModel "henyey-greenstein phase", declared
    // exact) against the GPU: shadow rays, a light from the side and one from the viewer.
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    const int size = 24;
    const ReferenceCamera camera = perspectiveCamera(size, osg::Vec3d(20, -50, 35), osg::Vec3d(0, 0, 0), 40, 10, 200);
    for (const auto& [g, light] : {std::pair{0.6, osg::Vec4(-1, 0, 0, 0)}, std::pair{-0.5, osg::Vec4(0.4f, -1, 0.7f, 0)}}) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), "ray", 1.0, {light});
        VolumeNode* node = findVolumeNodes(*scene)[0];
        node->settings.functions["Illumination"] = "henyey_greenstein";
        node->settings.parameters["anisotropy"] = g;
        const Pixels gpu = render(scene.get(), size, size, camera.view, camera.projection);
        const ReferenceSetup setup = referenceSetup(*scene, camera, {});
        const ReferenceImage truth = renderReference(setup.scene, camera, setup.options);
        const Difference d = differenceOf(gpu, truth, size);
        EXPECT_GT(d.covered, size * size / 8) << "g " << g;
        EXPECT_LT(d.worst, 4e-3) << "g " << g << ", rmse " << d.rmse;
        // And the phase function matters here: g = 0 is another picture.
        node->settings.parameters["anisotropy"] = 0.0;
        const ReferenceImage isotropic = renderReference(referenceSetup(*scene, camera, {}).scene, camera, setup.options);
        double change = 0.0;
        for (std::size_t i = 0; i < truth.rgba.size(); ++i) change = std::max(change, std::abs(truth.rgba[i] - isotropic.rgba[i]));
        EXPECT_GT(change, 0.05) << "g " << g;
    }
}

TEST_F(Shadowing, SchlickFollowsItsClosedFormAndStaysWithinItsBoundOfTheHenyeyGreensteinModel)
{
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    auto scene = [&](double g, const osg::Vec4& light) {
        osg::ref_ptr<VolumeScene> s = lit(block.get(), tf.get(), "ray", 1.0, {light});
        VolumeNode* node = findVolumeNodes(*s)[0];
        node->settings.functions["Illumination"] = "schlick";
        node->settings.parameters["anisotropy"] = g;
        return s;
    };
    // Its own closed form, against g = 0: from the viewer (cos = -1) (1 - k) / (1 + k), from the
    // side (cos = 0) 1 - k^2, with k = 1.55 g - 0.55 g^3.
    for (const auto& [light, cosTheta] : {std::pair{osg::Vec4(0, 0, 1, 0), -1.0}, std::pair{osg::Vec4(-1, 0, 0, 0), 0.0}}) {
        const osg::Vec4 isotropic = renderOrthoFromPlusZ(scene(0.0, light).get(), 8, 8, 32.0).at(4, 4);
        for (double g : {0.5, -0.5, 0.9}) {
            const double k = 1.55 * g - 0.55 * g * g * g;
            const osg::Vec4 p = renderOrthoFromPlusZ(scene(g, light).get(), 8, 8, 32.0).at(4, 4);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(p[c] / isotropic[c], (1 - k * k) / ((1 - k * cosTheta) * (1 - k * cosTheta)), 1e-4) << g;
        }
    }
    // Against the model it declares (the reference's Henyey-Greenstein phase at the same g).
    const double bound = ReferenceModelCatalog::instance().find("Illumination", "schlick")->bound;
    const int size = 24;
    const ReferenceCamera camera = perspectiveCamera(size, osg::Vec3d(20, -50, 35), osg::Vec3d(0, 0, 0), 40, 10, 200);
    for (const auto& [g, light] : {std::pair{0.5, osg::Vec4(-1, 0, 0, 0)}, std::pair{-0.5, osg::Vec4(0.4f, -1, 0.7f, 0)},
                                   std::pair{0.3, osg::Vec4(0.4f, -1, 0.7f, 0)}, std::pair{-0.3, osg::Vec4(-1, 0, 0, 0)},
                                   std::pair{0.5, osg::Vec4(0.4f, -1, 0.7f, 0)}, std::pair{-0.5, osg::Vec4(-1, 0, 0, 0)}}) {
        osg::ref_ptr<VolumeScene> s = scene(g, light);
        const Pixels gpu = render(s.get(), size, size, camera.view, camera.projection);
        const ReferenceSetup setup = referenceSetup(*s, camera, {});
        const Difference d = differenceOf(gpu, renderReference(setup.scene, camera, setup.options), size);
        EXPECT_LT(d.worst, bound) << "g " << g << ", rmse " << d.rmse;
        EXPECT_GT(d.worst, 1e-3) << "g " << g << ": an approximation, not the model itself";
    }
}

}  // namespace
}  // namespace volren::test
