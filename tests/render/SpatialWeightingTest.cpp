// Spatial weighting (the Weighting slot, implementation axes: weightX/Y/Z): each sample's opacity
// scaled by per-axis curves over the volume's normalised coordinates, in the DVR traversals,
// MIP, multi-channel members, shadow rays and the light volume; against closed forms, the
// reference, and the policy's choice.
#include "LitBlock.h"
#include "ReferenceComparison.h"
#include "TestData.h"

#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/RenderSettings.h>
#include <volume_model/SpatialWeighting.h>
#include <volume_reference/ReferenceSetup.h>
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/SceneSettings.h>

#include <cmath>
#include <map>

namespace volren::test {
namespace {

TEST(SpatialWeightingSettings, ReadBackExactlyAndRefuseBadCurves)
{
    RenderSettings s;
    std::string error;
    ASSERT_TRUE(s.set("weightZ", "0:0,0.123456789012345:1,1:0.3", error)) << error;
    EXPECT_EQ(spatialWeighting(s).axes[2].knots.size(), 3u);
    EXPECT_EQ(spatialWeighting(s).axes[2].knots[1].first, 0.123456789012345);
    EXPECT_TRUE(spatialWeighting(s).axes[0].identity());
    RenderSettings copy;
    ASSERT_TRUE(copy.set("weightz", s.get("weightZ"), error)) << error;
    EXPECT_EQ(copy, s);
    ASSERT_TRUE(s.set("weightX", "ramp:0.05", error)) << error;
    EXPECT_EQ(s.get("weightX"), "0:0,0.05:1,0.95:1,1:0");
    ASSERT_TRUE(s.set("weightX", "none", error)) << error;
    EXPECT_TRUE(spatialWeighting(s).axes[0].knots.empty());
    EXPECT_EQ(s.get("weightX"), "");
    EXPECT_EQ(RenderSettings::slotForKey("weighting"), "Weighting");

    std::string many;
    for (int i = 0; i <= int(WeightCurve::maxKnots); ++i) many += (i ? "," : "") + std::to_string(i / 20.0) + ":1";
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"0.5", "is not u:w"},          {"0:1,x:1", "is not u:w"},     {"0:1.5", "weight must be in [0, 1]"},
        {"0:-0.1", "weight must be in [0, 1]"}, {"1.2:1", "u must be in [0, 1]"}, {"0.5:1,0.5:0", "u must increase"},
        {"0.6:1,0.5:0", "u must increase"},     {"ramp:0", "0 < A <= 0.5"},  {"ramp:0.7", "0 < A <= 0.5"},
        {"0:nan", "is not u:w"},        {many, "at most 16 knots"}};
    for (const auto& [value, why] : bad) {
        RenderSettings r;
        EXPECT_FALSE(r.set("weightY", value, error)) << value;
        EXPECT_NE(error.find("weightY: "), std::string::npos) << error;
        EXPECT_NE(error.find(why), std::string::npos) << value << ": " << error;
        EXPECT_EQ(r, RenderSettings{}) << "a refused curve changes nothing: " << value;
    }
}


class SpatialWeightingRender : public RenderFixture
{
protected:
    static constexpr int n = 16;          ///< voxels per axis (spacing 1), centred at the origin
    static constexpr double alpha = 0.1;  ///< TF opacity of one voxel

    /// A white constant-opacity block of n^3 voxels of `value`, unlit, no early termination.
    static osg::ref_ptr<VolumeScene> block(Volume* volume, TransferFunction* tf)
    {
        osg::ref_ptr<VolumeNode> node = volumeNode(volume, tf);
        node->settings.earlyTerminationThreshold = 1.0;
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        scene->addChild(node.get());
        return scene;
    }
    static bool keyHas(const VolumeScene& scene, const std::string& part)
    {
        return scene.compositionKeys().at(0).find(part) != std::string::npos;
    }
};

TEST_F(SpatialWeightingRender, ALinearWeightAcrossTheViewScalesEachColumnsOpacity)
{
    // weightX = u: the ray through column u crosses n voxels of opacity u * alpha each, so its
    // coverage is 1 - (1 - u alpha)^n at any step (opacity correction is exact in a homogeneous column).
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, {n, n, n}, 200);
    osg::ref_ptr<VolumeScene> scene = block(volume.get(), constantTransferFunction({1, 1, 1, float(alpha)}).get());
    applySetting(*scene, "weightX", "0:0,1:1");
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);
    EXPECT_TRUE(keyHas(*scene, "Weighting=axes")) << scene->compositionKeys()[0];
    for (int x = 0; x < 32; ++x) {
        const double u = (x + 0.5) / 32.0;
        const double expected = 1.0 - std::pow(1.0 - u * alpha, n);
        ASSERT_NEAR(img.at(x, 16).a(), expected, 2e-3) << x;
        ASSERT_NEAR(img.at(x, 16).r(), expected, 2e-3) << x;
    }
    applySetting(*scene, "weightX", "none");  // back to no weighting: the slot is null again
    const Pixels plain = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);
    EXPECT_TRUE(keyHas(*scene, "Weighting=null")) << scene->compositionKeys()[0];
    EXPECT_NEAR(plain.at(3, 16).a(), 1.0 - std::pow(1.0 - alpha, n), 2e-3);
}

TEST_F(SpatialWeightingRender, ACurveOfManyKnotsIsEvaluatedOverAllItsSegments)
{
    // 16 knots (15 segments: the four vec4s of hinges the program compiles in for this axis), a
    // zig-zag across the view: column u's coverage is 1 - (1 - w(u) alpha)^n with w the curve.
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, {n, n, n}, 200);
    osg::ref_ptr<VolumeScene> scene = block(volume.get(), constantTransferFunction({1, 1, 1, float(alpha)}).get());
    std::string text;
    for (int i = 0; i < 16; ++i)
        text += (i ? "," : "") + std::to_string(0.03 + i * 0.062) + ":" + (i % 2 ? "0.2" : "1") + (i == 7 ? "5" : "");
    WeightCurve curve;
    std::string error;
    ASSERT_TRUE(WeightCurve::parse(text, curve, error)) << error;
    applySetting(*scene, "weightX", text);
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 64, 64, 16.0);
    EXPECT_TRUE(keyHas(*scene, "weightGroups=4,0,0;")) << scene->compositionKeys()[0];
    for (int x = 0; x < 64; ++x) {
        const double expected = 1.0 - std::pow(1.0 - curve((x + 0.5) / 64.0) * alpha, n);
        ASSERT_NEAR(img.at(x, 32).a(), expected, 2e-3) << x << " (weight " << curve((x + 0.5) / 64.0) << ")";
    }
}

TEST_F(SpatialWeightingRender, ARampAlongTheViewIntegratesTheWeightedOpticalDepth)
{
    // weightZ = ramp:0.25 along the ray: optical depth n * integral of -ln(1 - w(u) alpha) du,
    // here by a fine midpoint rule; the march samples half voxels (front to back and back to front).
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, {n, n, n}, 200);
    WeightCurve ramp;
    std::string error;
    ASSERT_TRUE(WeightCurve::parse("ramp:0.25", ramp, error));
    double depth = 0.0;
    const int steps = 100000;
    for (int i = 0; i < steps; ++i) depth += -std::log1p(-alpha * ramp((i + 0.5) / steps)) * n / steps;
    const double expected = -std::expm1(-depth);
    for (const char* traversal : {"dvr_front_to_back", "dvr_back_to_front"}) {
        osg::ref_ptr<VolumeScene> scene = block(volume.get(), constantTransferFunction({1, 1, 1, float(alpha)}).get());
        applySetting(*scene, "weightZ", "ramp:0.25");
        applySetting(*scene, "traversal", traversal);
        const Pixels img = renderOrthoFromPlusZ(scene.get(), 8, 8, 16.0);
        EXPECT_NEAR(img.at(4, 4).a(), expected, 2e-3) << traversal;
        EXPECT_LT(img.at(4, 4).a(), 1.0 - std::pow(1.0 - alpha, n) - 0.05) << "the ramp takes opacity away";
    }
}

TEST_F(SpatialWeightingRender, MipIgnoresWeightedOutSamplesAndScalesTheMaximumsOpacity)
{
    // A noisy last slice (z = n - 1, nearest the camera: 250) over a block of 100, TF opacity =
    // value / 255 (white): unweighted, MIP shows the slice (250/255); weighting it out (weight 0
    // above u = 0.9, where every sample still reads the slice through the trilinear filter) shows
    // the block (100/255): the ray meets the block's value first in the ramp (weights below 1),
    // and a tie shows as its most weighted sample.
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, {n, n, n}, 100);
    std::fill(volume->data() + n * n * (n - 1), volume->data() + n * n * n, std::uint8_t(250));
    volume->dirty();
    osg::ref_ptr<TransferFunction> tf = transferFunction({{0, {1, 1, 1, 0}}, {255, {1, 1, 1, 1}}}, 0, 255);
    osg::ref_ptr<VolumeScene> scene = block(volume.get(), tf.get());
    applySetting(*scene, "traversal", "mip");
    EXPECT_NEAR(renderOrthoFromPlusZ(scene.get(), 8, 8, 16.0).at(4, 4).a(), 250.0 / 255.0, 3e-3);
    applySetting(*scene, "weightZ", "0:1,0.88:1,0.9:0,1:0");
    const Pixels img = renderOrthoFromPlusZ(scene.get(), 8, 8, 16.0);
    EXPECT_TRUE(keyHas(*scene, "Weighting=axes")) << scene->compositionKeys()[0];
    EXPECT_NEAR(img.at(4, 4).a(), 100.0 / 255.0, 3e-3) << "the block's maximum at its largest weight, 1";
    // A weight across the view scales the maximum's opacity: u * 100/255 in column u.
    applySetting(*scene, "weightZ", "none");
    applySetting(*scene, "weightX", "0:0,1:1");
    std::fill(volume->data() + n * n * (n - 1), volume->data() + n * n * n, std::uint8_t(100));
    volume->dirty();
    const Pixels ramp = renderOrthoFromPlusZ(scene.get(), 32, 32, 16.0);
    for (int x = 0; x < 32; ++x) ASSERT_NEAR(ramp.at(x, 16).a(), (x + 0.5) / 32.0 * 100.0 / 255.0, 3e-3) << x;
}

TEST_F(SpatialWeightingRender, ThePolicyWeighsOnlyWhereANodeHasCurvesAndATraversalWeighsSamples)
{
    const CompositionPolicy policy;
    RenderSettings s;
    EXPECT_EQ(policy.choose(s, {}, {}).composition.functionFor("Weighting"), "null");
    std::string error;
    ASSERT_TRUE(s.set("weightZ", "ramp:0.1", error)) << error;
    EXPECT_EQ(policy.choose(s, {}, {}).composition.functionFor("Weighting"), "axes");
    // Only the segments the curves have are compiled in: a ramp's 3 on z (one vec4), none on x, y.
    using Defines = std::map<std::string, std::string>;
    EXPECT_EQ(policy.choose(s, {}, {}).composition.defines,
              (Defines{{"VOLREN_WEIGHT_GROUPS_X", "0"}, {"VOLREN_WEIGHT_GROUPS_Y", "0"}, {"VOLREN_WEIGHT_GROUPS_Z", "1"}}));
    ASSERT_TRUE(s.set("weightX", "0:0,0.1:1,0.2:0,0.3:1,0.4:0,0.5:1", error)) << error;  // 5 segments: two vec4s
    EXPECT_EQ(policy.choose(s, {}, {}).composition.defines,
              (Defines{{"VOLREN_WEIGHT_GROUPS_X", "2"}, {"VOLREN_WEIGHT_GROUPS_Y", "0"}, {"VOLREN_WEIGHT_GROUPS_Z", "1"}}));
    EXPECT_NE(policy.choose(s, {}, {}).composition.key().find("weightGroups=2,0,1;"), std::string::npos);
    ASSERT_TRUE(s.set("weightX", "none", error)) << error;
    s.functions["RayTraversal"] = "mip";
    EXPECT_EQ(policy.choose(s, {}, {}).composition.functionFor("Weighting"), "axes");
    s.functions["RayTraversal"] = "isosurface";  // does not weigh its samples: left null (and told once)
    EXPECT_EQ(policy.choose(s, {}, {}).composition.functionFor("Weighting"), "null");
    s.functions.erase("RayTraversal");
    s.forceNull.insert("Weighting");
    EXPECT_EQ(policy.choose(s, {}, {}).composition.functionFor("Weighting"), "null");
    EXPECT_TRUE(policy.choose(s, {}, {}).composition.defines.empty()) << "a null Weighting compiles nothing in";
    EXPECT_EQ(policy.resolve("Weighting", "on"), "axes");
    EXPECT_EQ(policy.resolve("Weighting", "off"), "null");
}

/// The shared 2-channel confocal stack with its first and last slices faded (weightZ=ramp:0.3),
/// per blending, against the reference of that blending with the same weighting.
class WeightedConfocal : public RenderFixture, public ::testing::WithParamInterface<const char*>
{
};

TEST_P(WeightedConfocal, TheWeightedStackMatchesTheWeightedReference)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string mode = GetParam();
    osg::ref_ptr<Volume> stack = readVolumeFile(sharedData("microscopy/xyzc_16bit__dna_conf_wf.tif"));
    osg::ref_ptr<osg::Group> loaded = makeDefaultScene(stack.get());
    auto* scene = dynamic_cast<VolumeScene*>(loaded.get());
    ASSERT_TRUE(scene);
    applySetting(*scene, "traversal", mode);
    applySetting(*scene, "earlyTermination", "1");
    applySetting(*scene, "samplerate", "2");
    const int size = 40;
    const osg::BoundingSphere bound = scene->getBound();
    const ReferenceCamera camera =
        perspectiveCamera(size, osg::Vec3d(bound.center()) + osg::Vec3d(0.6, -1.2, 0.9) * (2.2 * bound.radius()),
                          osg::Vec3d(bound.center()), 40, 0.5 * bound.radius(), 6.0 * bound.radius());
    const Pixels plain = render(scene, size, size, camera.view, camera.projection);
    applySetting(*scene, "weightZ", "ramp:0.3");
    const Pixels gpu = render(scene, size, size, camera.view, camera.projection);
    ASSERT_EQ(scene->programs().size(), 1u);
    const ReferenceSetup setup = referenceSetup(*scene, camera, {});
    ASSERT_EQ(setup.scene.volumes.size(), 2u);
    EXPECT_EQ(setup.scene.volumes[0].choice.at("Weighting"), "axes");
    const ReferenceImage truth = renderReference(setup.scene, camera, setup.options);
    const Difference d = differenceOf(gpu, truth, size);
    RecordProperty("rmse", std::to_string(d.rmse));
    RecordProperty("max", std::to_string(d.worst));
    double before = 0.0, after = 0.0;
    for (std::size_t i = 0; i < gpu.rgba.size(); ++i) before += plain.rgba[i].a(), after += gpu.rgba[i].a();
    EXPECT_LT(after, 0.9 * before) << "the faded slices take coverage away";
    EXPECT_GT(after, 0.1 * before);
    EXPECT_LT(d.rmse, mode == std::string("composite") ? 4e-4 : 6e-4) << "max " << d.worst;
    EXPECT_LT(d.worst, 0.03);
}

INSTANTIATE_TEST_SUITE_P(Modes, WeightedConfocal, ::testing::Values("composite", "additive", "mip"));

class WeightedShadows : public LitBlock
{
};

TEST_F(WeightedShadows, WeightedOutMaterialCastsNoShadow)
{
    // The half of the block nearest the light (z > 0) weighted 0: like a clip plane there, it
    // neither shows nor shadows; the rest is shadowed by itself only (ShadowingTest's clipped case).
    osg::ref_ptr<Volume> block = constantVolume(VoxelType::UInt8, {depthVoxels, depthVoxels, depthVoxels}, 100);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, float(alpha)));
    const std::string half = "0:1,0.5:1,0.500001:0,1:0";
    osg::ref_ptr<VolumeScene> unlitScene = lit(block.get(), tf.get(), "null");
    applySetting(*unlitScene, "weightZ", half);
    const osg::Vec4 unlit = renderOrthoFromPlusZ(unlitScene.get(), 8, 8, 32.0).at(4, 4);
    const int first = int(depthVoxels / step) / 2;
    const double ratio = expectedRatio(first, [&](int i) { return std::exp(-sigma * (i - first + 0.5) * step); });
    // Fine shadow steps find the weight's edge exactly; shadow rays take 1600 steps here, and a
    // weight evaluated with loops was cut short by llvmpipe's limit on a fragment's loop iterations.
    for (const char* shadowing : {"ray", "light_volume"}) {
        osg::ref_ptr<VolumeScene> scene = lit(block.get(), tf.get(), shadowing);
        findVolumeNodes(*scene)[0]->settings.parameters["shadowStepFactor"] = 0.02;
        const osg::Vec4 whole = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
        applySetting(*scene, "weightZ", half);  // a light volume is rebuilt for the new weighting
        const osg::Vec4 shadowed = renderOrthoFromPlusZ(scene.get(), 8, 8, 32.0).at(4, 4);
        EXPECT_NE(scene->compositionKeys()[0].find("Weighting=axes"), std::string::npos) << scene->compositionKeys()[0];
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(shadowed[c] / unlit[c], ratio, std::string(shadowing) == "ray" ? 1e-3 : 0.02)
                << shadowing << " channel " << c;
        EXPECT_LT(shadowed.r(), whole.r()) << shadowing << ": the weighted-out front half no longer shows";
    }
}

}  // namespace
}  // namespace volren::test
