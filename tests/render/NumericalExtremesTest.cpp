// Numerical extremes: opacities at the ends of their range, a narrow TF spike, 16-bit, 12-bit,
// signed and float data with huge ranges, denormals and non-finite voxels, tiny and thin volumes,
// spacing ratios of 1:1000, cameras on the box surface and far away, zero gradients under
// lighting, 1x1 and 4096x4096 viewports. Each against a closed form or the CPU reference, with
// its error bound; none may give a NaN pixel or a GL error (RenderFixture fails on GL errors).
// (Sample distances from 1/1000 to 100 voxels and opacities 1e-7 and 0.999: OpacityCorrectionTest;
// NaN and Inf voxels in noise: DeterminismTest.)
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_reference/ReferenceSetup.h>

#include <osg/LightSource>

#include <cmath>
#include <cstring>
#include <limits>

namespace volren::test {
namespace {

class NumericalExtremes : public RenderFixture
{
protected:
    /// Every channel of every pixel finite and in [0, 1].
    static void expectFiniteAndBounded(const Pixels& p)
    {
        std::size_t bad = 0;
        for (const osg::Vec4& c : p.rgba)
            for (int k = 0; k < 4; ++k) bad += !(c[k] >= 0.0f && c[k] <= 1.0f);
        EXPECT_EQ(bad, 0u) << "channels NaN, infinite or outside [0, 1]";
    }

    /// Orthographic view from +z, `view` units across, as a ReferenceCamera and RenderFixture use it.
    static ReferenceCamera orthoCamera(int size, double view, double distance = 100.0)
    {
        ReferenceCamera c;
        c.width = c.height = size;
        c.view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, distance), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
        c.projection = osg::Matrixd::ortho(-view / 2, view / 2, -view / 2, view / 2, 1.0, 2.0 * distance);
        return c;
    }

    /// GPU (no jitter, no early termination, `rate` samples per voxel) against the reference:
    /// the largest absolute channel error.
    static double worstAgainstReference(osg::Node* scene, const ReferenceCamera& camera)
    {
        const Pixels gpu = render(scene, camera.width, camera.height, camera.view, camera.projection);
        expectFiniteAndBounded(gpu);
        ReferenceOptions options;
        options.tolerance = 1e-5;
        const ReferenceImage truth = renderReference(ReferenceScene::collect(*scene), camera, options);
        double worst = 0.0;
        for (int y = 0; y < camera.height; ++y)
            for (int x = 0; x < camera.width; ++x)
                for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(gpu.at(x, y)[k] - truth.at(x, y, k)));
        return worst;
    }

    static osg::ref_ptr<VolumeNode> exactNode(Volume* volume, TransferFunction* tf, const char* rate = "2")
    {
        osg::ref_ptr<VolumeNode> node = volumeNode(volume, tf);
        std::string error;
        EXPECT_TRUE(node->settings.set("earlyTermination", "1", error)) << error;
        EXPECT_TRUE(node->settings.set("samplerate", rate, error)) << error;
        return node;
    }

    /// A volume of `dims` whose stored values rise linearly along z from `lo` to `hi`.
    static osg::ref_ptr<Volume> rampAlongZ(VoxelType type, const osg::Vec3i& dims, double lo, double hi)
    {
        osg::ref_ptr<Volume> v = constantVolume(type, dims, 0.0);
        const std::size_t slice = std::size_t(dims.x()) * dims.y();
        for (std::size_t i = 0; i < v->voxelCount(); ++i) {
            const double value = lo + (hi - lo) * double(i / slice) / double(dims.z() - 1);
            switch (type) {
            case VoxelType::UInt16: { const auto s = std::uint16_t(std::lround(value)); std::memcpy(v->data() + 2 * i, &s, 2); break; }
            case VoxelType::Int16: { const auto s = std::int16_t(std::lround(value)); std::memcpy(v->data() + 2 * i, &s, 2); break; }
            case VoxelType::Int8: v->data()[i] = std::uint8_t(std::int8_t(std::lround(value))); break;
            case VoxelType::UInt8: v->data()[i] = std::uint8_t(std::lround(value)); break;
            case VoxelType::Float32: { const auto f = float(value); std::memcpy(v->data() + 4 * i, &f, 4); break; }
            }
        }
        v->dirty();
        return v;
    }

    /// A TF over [lo, hi] whose colour and opacity rise linearly with the value.
    static osg::ref_ptr<TransferFunction> rampTf(double lo, double hi, float alpha = 0.2f)
    {
        return transferFunction({{lo, {0, 0.2f, 1, 0}}, {hi, {1, 0.8f, 0, alpha}}}, lo, hi);
    }
};

TEST_F(NumericalExtremes, OpacitiesZeroTinyNearOneAndOneFollowTheSlabClosedForm)
{
    // 8 voxels of medium along the view: alpha 1 - (1 - a)^8.
    for (const double a : {0.0, 1e-7, 1.0 - 1e-7, 1.0}) {
        const float stored = float(a);
        auto node = exactNode(constantVolume(VoxelType::UInt8, {8, 8, 8}, 100).get(),
                              constantTransferFunction(osg::Vec4(0.25f, 0.5f, 1.0f, stored)).get());
        const Pixels p = renderOrthoFromPlusZ(node.get(), 16, 16, 16.0);
        expectFiniteAndBounded(p);
        const double expected = stored >= 1.0f ? 1.0 : -std::expm1(8.0 * std::log1p(-double(stored)));
        EXPECT_NEAR(p.at(8, 8).a(), expected, 2e-7 + 1e-5 * expected) << "alpha " << a;
        EXPECT_NEAR(p.at(8, 8).b(), expected, 2e-7 + 1e-5 * expected) << "alpha " << a;
        EXPECT_NEAR(p.at(8, 8).g(), 0.5 * expected, 2e-7 + 1e-5 * expected) << "alpha " << a;
        EXPECT_EQ(p.at(0, 0), osg::Vec4(0, 0, 0, 0)) << "outside the box";
    }
}

TEST_F(NumericalExtremes, NarrowSpikeIsMissedByCoarseStepsAndFoundByFineOnes)
{
    // Values rise 4 per voxel along z; the TF is opaque-ish only for 126..130, a layer 1 voxel
    // thick. The reference integrates it exactly; the GPU's error shrinks with its step.
    // Measured on llvmpipe (max abs error): 0.24 at 1 sample/voxel, 0.0036 at 4 and at 16.
    osg::ref_ptr<Volume> ramp = rampAlongZ(VoxelType::UInt8, {4, 4, 64}, 0.0, 252.0);
    osg::ref_ptr<TransferFunction> spike = transferFunction(
        {{0, {1, 1, 1, 0}}, {126, {1, 1, 1, 0}}, {128, {1, 1, 1, 0.6f}}, {130, {1, 1, 1, 0}}, {255, {1, 1, 1, 0}}}, 0, 255);
    const ReferenceCamera camera = orthoCamera(8, 8.0);
    std::vector<double> errors;
    for (const char* rate : {"1", "4", "16"}) {
        auto node = exactNode(ramp.get(), spike.get(), rate);
        errors.push_back(worstAgainstReference(node.get(), camera));
    }
    RecordProperty("max_error_1_4_16", std::to_string(errors[0]) + " " + std::to_string(errors[1]) + " " +
                                           std::to_string(errors[2]));
    EXPECT_GT(errors[0], 0.03) << "one sample per voxel visibly under-samples the spike";
    EXPECT_LT(errors[1], 0.25 * errors[0]);
    EXPECT_LT(errors[2], 0.01) << "what remains is the 8-bit filtering of the ramp, not the step";
}

TEST_F(NumericalExtremes, SixteenBitTwelveBitSignedAndEightBitSignedDataMatchTheReference)
{
    // Ramps over the whole range of each type (and 12 bits of a 16-bit file) through a TF over
    // that range: the GPU's normalised textures and value window against the reference.
    // Measured on llvmpipe (max abs error): 6.9e-5 for uint16, 12-bit and int16, 2.0e-4 for int8.
    struct Case { VoxelType type; double lo, hi; const char* what; };
    for (const Case& c : {Case{VoxelType::UInt16, 0, 65535, "uint16 full range"},
                          Case{VoxelType::UInt16, 0, 4095, "12 bits in uint16"},
                          Case{VoxelType::Int16, -32768, 32767, "int16 full range"},
                          Case{VoxelType::Int8, -128, 127, "int8 full range"}}) {
        osg::ref_ptr<Volume> v = rampAlongZ(c.type, {4, 4, 16}, c.lo, c.hi);
        auto node = exactNode(v.get(), rampTf(c.lo, c.hi).get(), "4");
        const double worst = worstAgainstReference(node.get(), orthoCamera(8, 8.0));
        RecordProperty(std::string("max_error ") + c.what, std::to_string(worst));
        EXPECT_LT(worst, 2e-3) << c.what;
    }
}

TEST_F(NumericalExtremes, FloatDataWithHugeRangesDenormalsAndNonFiniteVoxels)
{
    // Values from -1e30 to 1e30 with denormals (+-1e-40) among them, NaN and +-Inf voxels at the
    // edge, a TF over [-1e30, 1e30]. A NaN voxel makes every sample interpolated from it NaN,
    // which classifies as empty; an Inf voxel makes its cell's samples infinite, clamped to the
    // TF's end (in both renderers; where an interpolation weight is 0 in one and 1e-7 in the
    // other they differ, so the comparison stays more than one voxel away from those voxels).
    // The whole image stays finite; inside, GPU and reference agree.
    osg::ref_ptr<Volume> v = rampAlongZ(VoxelType::Float32, {8, 8, 16}, -1e30, 1e30);
    auto* f = reinterpret_cast<float*>(v->data());
    auto at = [&](int x, int y, int z) -> float& { return f[(z * 8 + y) * 8 + x]; };
    at(3, 3, 3) = 1e-40f;  // denormals in the middle
    at(4, 4, 4) = -1e-40f;
    at(0, 0, 12) = std::numeric_limits<float>::quiet_NaN();
    at(7, 7, 13) = std::numeric_limits<float>::infinity();
    at(7, 7, 14) = -std::numeric_limits<float>::infinity();
    v->dirty();
    auto node = exactNode(v.get(), rampTf(-1e30, 1e30).get(), "4");
    const ReferenceCamera camera = orthoCamera(16, 8.0);
    const Pixels p = render(node.get(), 16, 16, camera.view, camera.projection);
    expectFiniteAndBounded(p);
    const ReferenceImage truth = renderReference(ReferenceScene::collect(*node), camera);
    // Pixels 6..9 see columns 3..4 (their samples interpolate columns 2..5 only).
    for (int y = 6; y <= 9; ++y)
        for (int x = 6; x <= 9; ++x)
            for (int k = 0; k < 4; ++k) EXPECT_NEAR(p.at(x, y)[k], truth.at(x, y, k), 2e-3) << x << "," << y;
    EXPECT_GT(p.at(8, 8).a(), 0.1f) << "the medium is there";
}

TEST_F(NumericalExtremes, TinyThinAndLongVolumesFollowTheSlabClosedForm)
{
    // Homogeneous boxes: 1x1x1, 1x1x64, 2x2x2 and 4096x4x4 voxels; looking down z through each
    // box's middle from just above it, the medium is dims.z voxels deep.
    for (const osg::Vec3i dims : {osg::Vec3i(1, 1, 1), osg::Vec3i(1, 1, 64), osg::Vec3i(2, 2, 2), osg::Vec3i(4096, 4, 4)}) {
        auto node = exactNode(constantVolume(VoxelType::UInt8, dims, 100).get(),
                              constantTransferFunction(osg::Vec4(1, 1, 1, 0.05f)).get());
        const double top = dims.z() / 2.0 + 1.0;
        const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, top), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
        const Pixels p = render(node.get(), 9, 9, view, osg::Matrixd::ortho(-0.45, 0.45, -0.45, 0.45, 0.5, 2.0 * top));
        expectFiniteAndBounded(p);
        const double expected = -std::expm1(dims.z() * std::log1p(-double(0.05f)));
        EXPECT_NEAR(p.at(4, 4).a(), expected, 1e-5) << dims.x() << "x" << dims.y() << "x" << dims.z();
    }
}

TEST_F(NumericalExtremes, SpacingRatioOfOneToAThousand)
{
    // Spacing (0.001, 1, 1): the box is 0.008 x 8 x 8 units and the reference length 0.001, so
    // 8 units of depth are 8000 reference lengths; alpha 1e-5 per reference length gives
    // 1 - (1 - 1e-5)^8000. Marched at half that length the ray takes 16000 steps.
    auto node = exactNode(constantVolume(VoxelType::UInt8, {8, 8, 8}, 100, {0.001, 1.0, 1.0}).get(),
                          constantTransferFunction(osg::Vec4(1, 1, 1, 1e-5f)).get());
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 10), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    const Pixels p = render(node.get(), 8, 8, view, osg::Matrixd::ortho(-0.008, 0.008, -8.0, 8.0, 1.0, 20.0));
    expectFiniteAndBounded(p);
    const double expected = -std::expm1(8000.0 * std::log1p(-double(1e-5f)));
    EXPECT_NEAR(p.at(4, 4).a(), expected, 1e-4 * expected) << "pixel (0.001, 1) inside the box";
}

TEST_F(NumericalExtremes, BoxesFarDownTheNearToFarRangeLosePrecision)
{
    // Rays are parameterised in float from the near plane (t = 0) to the far plane (t = 1): a box
    // at t ~ 0.5 of a 41000-unit range sits where t has ulps of ~0.002 units, and its 4-unit depth
    // is measured that coarsely. Measured on llvmpipe: below 1e-6 relative error of the slab's
    // opacity with the box near the near plane, 1.9e-4 with the camera 20000 units away. A known
    // limitation (README).
    auto node = exactNode(constantVolume(VoxelType::UInt8, {8, 8, 4}, 100).get(),
                          constantTransferFunction(osg::Vec4(1, 1, 1, 0.05f)).get());
    const double expected = -std::expm1(4.0 * std::log1p(-double(0.05f)));
    double errors[2];
    int i = 0;
    for (const double distance : {10.0, 20000.0}) {
        const osg::Matrixd view =
            osg::Matrixd::lookAt(osg::Vec3d(0, 0, distance), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
        const Pixels p = render(node.get(), 9, 9, view, osg::Matrixd::ortho(-4.5, 4.5, -4.5, 4.5, 1.0, 2.0 * distance + 1000.0));
        expectFiniteAndBounded(p);
        errors[i++] = std::abs(p.at(4, 4).a() - expected) / expected;
    }
    RecordProperty("relative_error_near_far", std::to_string(errors[0]) + " " + std::to_string(errors[1]));
    EXPECT_LT(errors[0], 1e-5);
    EXPECT_LT(errors[1], 1e-3);
}

TEST_F(NumericalExtremes, CameraOnTheBoxSurfaceAndFarAway)
{
    auto node = exactNode(constantVolume(VoxelType::UInt8, {16, 16, 16}, 100).get(),
                          constantTransferFunction(osg::Vec4(1, 1, 1, 0.1f)).get());
    const double whole = -std::expm1(16.0 * std::log1p(-double(0.1f)));
    // Eye exactly on the front face (z = 8), looking down -z: the whole depth is ahead.
    const osg::Matrixd onFace = osg::Matrixd::lookAt(osg::Vec3d(0.5, 0.5, 8.0), osg::Vec3d(0.5, 0.5, 0.0), osg::Vec3d(0, 1, 0));
    const Pixels near = render(node.get(), 33, 33, onFace, osg::Matrixd::perspective(20.0, 1.0, 1e-4, 100.0));
    expectFiniteAndBounded(near);
    EXPECT_NEAR(near.at(16, 16).a(), whole, 2e-4);
    // Far away (1e5 units, 0.01 degree field of view): the box covers the middle of the view.
    const osg::Matrixd far = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 1e5), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    const Pixels tiny = render(node.get(), 33, 33, far, osg::Matrixd::perspective(0.02, 1.0, 9e4, 1.1e5));
    expectFiniteAndBounded(tiny);
    EXPECT_NEAR(tiny.at(16, 16).a(), whole, 2e-4);
    EXPECT_EQ(tiny.at(0, 0).a(), 0.0f);
}

TEST_F(NumericalExtremes, ZeroGradientsUnderLightingFaceTheViewer)
{
    // A homogeneous volume has no gradient anywhere: the normal falls back to the view direction,
    // so a headlight gives full diffuse and the highlight: colour = albedo (ambient + 1) + specular,
    // times the slab's alpha; the reference agrees, and nothing is NaN.
    auto node = exactNode(constantVolume(VoxelType::UInt8, {8, 8, 8}, 100).get(),
                          constantTransferFunction(osg::Vec4(0.5f, 0.25f, 0.125f, 0.1f)).get());
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(node.get());
    osg::ref_ptr<osg::LightSource> headlight = new osg::LightSource;
    headlight->setReferenceFrame(osg::LightSource::ABSOLUTE_RF);
    headlight->getLight()->setPosition(osg::Vec4(0, 0, 1, 0));
    headlight->getLight()->setDiffuse(osg::Vec4(1, 1, 1, 1));
    scene->addChild(headlight.get());
    const ReferenceCamera camera = orthoCamera(16, 16.0);
    const Pixels p = render(scene.get(), 16, 16, camera.view, camera.projection);
    expectFiniteAndBounded(p);
    const double alpha = -std::expm1(8.0 * std::log1p(-double(0.1f)));
    const RenderSettings defaults;
    const osg::Vec3d albedo(0.5, 0.25, 0.125);
    const ReferenceImage truth = renderReference(referenceScene(*scene), camera);
    for (int k = 0; k < 3; ++k) {
        const double lit = albedo[k] * (defaults.number("ambient") + 1.0) + defaults.number("specular");
        EXPECT_NEAR(truth.at(8, 8, k), lit * alpha, 1e-6) << "reference, channel " << k;
        EXPECT_NEAR(p.at(8, 8)[k], lit * alpha, 1e-3) << "GPU, channel " << k;
    }
}

TEST_F(NumericalExtremes, NaNVoxelsUnderLightingShadeTheirNeighboursAsAZeroGradient)
{
    // NaN voxels in a lit float ramp. A sample interpolated from one is NaN (empty); a sample
    // whose gradient taps read one has a NaN gradient, which tells nothing of a boundary: its
    // normal is the view direction and lighting_surface leaves it unlit, in both renderers. (Until
    // 2026-12-07 max() passed over the NaN component in both, and the normal came out NaN:
    // the GPU's pixel went black, the reference's went NaN: 0.068 apart.) Samples at a quarter
    // voxel from the voxel centres keep every interpolation weight away from 0. The NaN voxels
    // are two voxels from the border or more: one at y = 1 makes the two renderers' opacity
    // differ by 0.012 on the border row, with or without lighting, where the GPU is the more
    // transparent: most likely llvmpipe clamps the coordinate to the border texel's centre and
    // still lerps towards the next texel with weight 0, and 0 * NaN is NaN.
    osg::ref_ptr<Volume> v = rampAlongZ(VoxelType::Float32, {8, 8, 16}, 0.0, 1.0);
    auto* f = reinterpret_cast<float*>(v->data());
    for (const osg::Vec3i& at : {osg::Vec3i(4, 4, 8), osg::Vec3i(2, 5, 11), osg::Vec3i(5, 2, 4)})
        f[(at.z() * 8 + at.y()) * 8 + at.x()] = std::numeric_limits<float>::quiet_NaN();
    v->dirty();
    for (const char* shading : {"null", "lighting", "lighting_surface"}) {
        osg::ref_ptr<VolumeNode> node = exactNode(v.get(), rampTf(0.0, 1.0, 0.3f).get());
        node->settings.functions["Shading"] = shading;
        node->settings.functions["Illumination"] = "lambert";
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        scene->addChild(node.get());
        osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
        light->getLight()->setPosition(osg::Vec4(0.3f, -0.4f, 1.0f, 0.0f));
        scene->addChild(light.get());
        const double worst = worstAgainstReference(scene.get(), orthoCamera(16, 8.0));
        EXPECT_LT(worst, 2e-3) << shading;
    }
}

TEST_F(NumericalExtremes, OneByOneAndHugeViewports)
{
    auto node = exactNode(constantVolume(VoxelType::UInt8, {8, 8, 8}, 100).get(),
                          constantTransferFunction(osg::Vec4(1, 1, 1, 0.1f)).get());
    const double expected = -std::expm1(8.0 * std::log1p(-double(0.1f)));
    const Pixels one = renderOrthoFromPlusZ(node.get(), 1, 1, 4.0);
    expectFiniteAndBounded(one);
    EXPECT_NEAR(one.at(0, 0).a(), expected, 1e-5);
    // 4096 x 4096 (16.7 million rays, 256 MiB of float RGBA read back), the box filling the middle.
    const Pixels huge = renderOrthoFromPlusZ(node.get(), 4096, 4096, 16.0);
    expectFiniteAndBounded(huge);
    EXPECT_NEAR(huge.at(2048, 2048).a(), expected, 1e-5);
    EXPECT_NEAR(huge.at(1100, 3000).a(), expected, 1e-5);  // (-4.8, 3.7): inside the 8-unit box
    EXPECT_EQ(huge.at(10, 10).a(), 0.0f);
    renderer(16, 16);  // let go of the 4096 x 4096 framebuffer
}

/// A soft float ball of 16^3 voxels at `spacing` (every axis), drawn at 24 x 24 from a view
/// scaled with it: the same picture at every scale.
Pixels ballAtScale(double spacing)
{
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::Float32, {16, 16, 16});
    auto* v = reinterpret_cast<float*>(volume->data());
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                v[x + 16 * (y + 16 * z)] = float(std::max(0.0, 1.0 - std::hypot(x - 7.5, y - 7.5, z - 7.5) / 8.0));
    volume->setSpacing({spacing, spacing, spacing});
    volume->dirty();
    osg::ref_ptr<VolumeNode> node =
        makeVolumeNode(volume.get(), transferFunction({{0.0, osg::Vec4(0, 0, 0, 0)}, {1.0, osg::Vec4(1, 0.7f, 0.4f, 0.6f)}}, 0.0, 1.0).get());
    const osg::Vec3d eye = osg::Vec3d(20, -30, 15) * spacing;
    const double distance = eye.length(), radius = 14.0 * spacing;
    return RenderFixture::render(node.get(), 24, 24, osg::Matrixd::lookAt(eye, osg::Vec3d(), osg::Vec3d(0, 0, 1)),
                                 osg::Matrixd::perspective(30.0, 1.0, distance - radius, distance + radius));
}

TEST_F(NumericalExtremes, SpacingFromNanometresToTenTimesTheEarthsOrbitDrawsOnePicture)
{
    // The ray's matrices come from the box's scale and the camera's: inverting their product in
    // float overflowed once the box spanned ~1e9 units (spacing 3e7 here), and the image was black.
    const Pixels unit = ballAtScale(1.0);
    double covered = 0.0;
    for (const osg::Vec4& p : unit.rgba) covered += p.a() > 0.05;
    ASSERT_GT(covered, 100.0);
    for (double spacing : {1e-9, 1e-3, 1e3, 1e7, 1e8, 1e10, 1e11, 1e12}) {
        const Pixels scaled = ballAtScale(spacing);
        double worst = 0.0;
        for (std::size_t i = 0; i < unit.rgba.size(); ++i)
            for (int c = 0; c < 4; ++c) worst = std::max(worst, double(std::abs(unit.rgba[i][c] - scaled.rgba[i][c])));
        EXPECT_LT(worst, 2e-3) << "spacing " << spacing;
    }
}

}  // namespace
}  // namespace volren::test
