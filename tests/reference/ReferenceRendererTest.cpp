// The CPU reference renderer against closed forms of the emission-absorption integral (this
// suite links the model and the reference only; the GPU against the reference is in render/).
#include "TestData.h"

#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipPlaneNode.h>
#include <volume_model/ReadVolume.h>
#include <volume_reference/ReferenceRenderer.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <gtest/gtest.h>
#include <osg/LightSource>
#include <osg/MatrixTransform>
#include <osgDB/ReadFile>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace volren::test {
namespace {

/// The parameters the reference reads (ambient, specular, cone start, ...) are declared by the
/// renderer's implementations: their registry fills the model's catalog.
class Declared : public ::testing::Environment
{
    void SetUp() override { ShaderFunctionRegistry::instance(); }
};
const auto* const declared = ::testing::AddGlobalTestEnvironment(new Declared);

/// Orthographic camera looking down -z at the origin, `view` world units across.
ReferenceCamera orthoFromPlusZ(int size, double view)
{
    ReferenceCamera c;
    c.width = c.height = size;
    c.view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 100), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    c.projection = osg::Matrixd::ortho(-view / 2, view / 2, -view / 2, view / 2, 1, 200);
    return c;
}

osg::ref_ptr<osg::Group> withNode(osg::ref_ptr<VolumeNode> node)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(node.get());
    return root;
}

TEST(ReferenceRenderer, HomogeneousMediumGivesTheClosedFormAtAnySpacing)
{
    // Colour c, TF opacity a per smallest spacing: a path of L world units gives alpha
    // 1 - (1-a)^(L / spacing) and colour c times that alpha.
    for (const osg::Vec3d spacing : {osg::Vec3d(1, 1, 1), osg::Vec3d(1, 1, 4), osg::Vec3d(0.5, 2, 3)}) {
        const double a = 0.1;
        auto node = makeVolumeNode(constantVolume(VoxelType::UInt8, {16, 16, 16}, 50, spacing).get(),
                                              constantTransferFunction(osg::Vec4(0.2f, 0.5f, 1.0f, float(a))).get());
        const ReferenceImage img = renderReference(ReferenceScene::collect(*withNode(node)), orthoFromPlusZ(8, 4.0));
        const double unit = std::min({spacing.x(), spacing.y(), spacing.z()});
        const double alpha = 1.0 - std::pow(1.0 - double(float(a)), 16.0 * spacing.z() / unit);
        EXPECT_NEAR(img.at(4, 4, 3), alpha, 1e-12) << spacing.z();
        EXPECT_NEAR(img.at(4, 4, 1), double(0.5f) * alpha, 1e-12);
        EXPECT_EQ(img.unconverged, 0u);
    }
}

TEST(ReferenceRenderer, RampBetweenTwoMediaMatchesTheIntegratedExtinction)
{
    // Two slabs (values 0 and 255) meet at z = 8; the trilinear field ramps linearly between the
    // voxel centres 7.5 and 8.5, and so does the TF's opacity, from a1 to a2. With black emission
    // the alpha is 1 - exp(-integral of sigma), sigma = -ln(1 - alpha(z)) (spacing 1):
    // 7.5 sigma1 + 7.5 sigma2 + the ramp's integral (1/q) [u ln u - u] from u0 = 1 - a1 to u1 = 1 - a2.
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt8, {4, 4, 16});
    for (std::size_t i = 0; i < v->voxelCount(); ++i) v->data()[i] = (i / 16) >= 8 ? 255 : 0;
    v->dirty();
    const double a1 = 0.05, a2 = 0.6;
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(0, 0, 0, float(a1)));
    tf->setPoint(255.0, osg::Vec4(0, 0, 0, float(a2)));
    const double f1 = double(float(a1)), f2 = double(float(a2));
    const double s1 = -std::log1p(-f1), s2 = -std::log1p(-f2);
    const double q = f2 - f1, u0 = 1.0 - f1, u1 = 1.0 - f2;
    const double ramp = ((u1 * std::log(u1) - u1) - (u0 * std::log(u0) - u0)) / q;
    const double expected = 1.0 - std::exp(-(7.5 * s1 + 7.5 * s2 + ramp));
    auto node = makeVolumeNode(v.get(), tf.get());
    ReferenceOptions options;
    options.tolerance = 1e-7;
    const ReferenceImage img = renderReference(ReferenceScene::collect(*withNode(node)), orthoFromPlusZ(4, 2.0), options);
    EXPECT_NEAR(img.at(2, 2, 3), expected, 1e-6);
    EXPECT_EQ(img.unconverged, 0u);
    EXPECT_LT(img.finestStepUsed, 0.25) << "the ramp needed finer steps than the first";
}

TEST(ReferenceRenderer, ClipPlaneCameraInsideAndOverlappingVolumesFollowTheirClosedForms)
{
    const double a = 0.1, fa = double(float(a));
    auto medium = [&] {
        return makeVolumeNode(constantVolume(VoxelType::UInt8, {16, 16, 16}, 50).get(),
                                         constantTransferFunction(osg::Vec4(1, 1, 1, float(a))).get());
    };
    // A plane keeping z <= 0 leaves 8 units of the 16.
    osg::ref_ptr<osg::Group> clipped = withNode(medium());
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(0, 0, -1, 0);
    clipped->addChild(plane.get());
    EXPECT_NEAR(renderReference(ReferenceScene::collect(*clipped), orthoFromPlusZ(4, 2.0)).at(2, 2, 3),
                1.0 - std::pow(1.0 - fa, 8.0), 1e-12);

    // A perspective camera at the centre looking along +x: the centre pixel's ray runs from the
    // near plane (0.5) to the box face at x = 8.
    ReferenceCamera inside;
    inside.width = inside.height = 9;
    inside.view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 0), osg::Vec3d(1, 0, 0), osg::Vec3d(0, 0, 1));
    inside.projection = osg::Matrixd::perspective(20, 1, 0.5, 100);
    EXPECT_NEAR(renderReference(ReferenceScene::collect(*withNode(medium())), inside).at(4, 4, 3),
                1.0 - std::pow(1.0 - fa, 7.5), 1e-9);

    // Two media overlapping by 8 units along z add their extinctions there: 24 units of path,
    // 8 of them doubled, as if 32 units of one.
    osg::ref_ptr<osg::Group> two = new osg::Group;
    two->addChild(medium().get());
    osg::ref_ptr<osg::MatrixTransform> shifted = new osg::MatrixTransform(osg::Matrixd::translate(0, 0, 8));
    shifted->addChild(medium().get());
    two->addChild(shifted.get());
    EXPECT_NEAR(renderReference(ReferenceScene::collect(*two), orthoFromPlusZ(4, 2.0)).at(2, 2, 3),
                1.0 - std::pow(1.0 - fa, 32.0), 1e-12);
}

TEST(ReferenceRenderer, HomogeneousSphereFollowsItsChordLengthToOneInAMillion)
{
    // A homogeneous medium kept only inside a sphere of radius 10 (an ellipsoid clip shape, exact
    // by its CPU definition): the ray at distance r from the centre crosses 2 sqrt(100 - r^2)
    // units, so alpha = 1 - (1 - a)^(2 sqrt(100 - r^2)). Converged to 1e-7 per ray.
    const double a = 0.05;
    auto node = makeVolumeNode(constantVolume(VoxelType::UInt8, {24, 24, 24}, 100).get(),
                                          constantTransferFunction(osg::Vec4(1, 1, 1, float(a))).get());
    osg::ref_ptr<osg::Group> root = withNode(node);
    osg::ref_ptr<ClipEllipsoidNode> sphere = new ClipEllipsoidNode;
    sphere->radii = osg::Vec3d(10, 10, 10);
    root->addChild(sphere.get());
    ReferenceOptions options;
    options.tolerance = 1e-7;
    options.finestStep = 1.0 / (1 << 20);
    const ReferenceImage img = renderReference(ReferenceScene::collect(*root), orthoFromPlusZ(2, 16.0), options);
    EXPECT_EQ(img.unconverged, 0u);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            const double px = (x + 0.5) * 8.0 - 8.0, py = (y + 0.5) * 8.0 - 8.0;  // (+-4, +-4) world units
            const double chord = 2.0 * std::sqrt(100.0 - px * px - py * py);
            EXPECT_NEAR(img.at(x, y, 3), -std::expm1(chord * std::log1p(-double(float(a)))), 1e-6) << x << "," << y;
        }
}

TEST(ReferenceRenderer, LitRampFollowsTheBlinnPhongAndSurfaceClosedForms)
{
    // Values rising along x (10 per voxel), one colour and opacity for all of them: the normal is
    // -x everywhere (from dense to empty; both gradient conventions agree inside), a directional
    // light from (-1, 0, 1) and the view along -z give n.l = 1/sqrt 2 and the half vector
    // (-1, 0, 1 + sqrt 2)/|..|; the lit colour is constant, so the pixel is that colour times the
    // slab's alpha.
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt8, {16, 8, 8});
    for (std::size_t i = 0; i < v->voxelCount(); ++i) v->data()[i] = std::uint8_t(20 + 10 * (i % 16));
    v->dirty();
    const osg::Vec4 albedo(0.8f, 0.5f, 0.25f, 0.1f);
    auto node = makeVolumeNode(v.get(), constantTransferFunction(albedo).get());
    std::string error;
    ASSERT_TRUE(node->settings.set("ambient", "0.2", error)) << error;
    ASSERT_TRUE(node->settings.set("specular", "0.3", error)) << error;
    ASSERT_TRUE(node->settings.set("shininess", "24", error)) << error;
    // The reference models what it is told (the renderer's policy picks these for a lit scene).
    node->settings.functions["Shading"] = "lighting";
    node->settings.functions["Illumination"] = "blinn_phong";
    osg::ref_ptr<osg::Group> root = withNode(node);
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(-1, 0, 1, 0));
    light->getLight()->setDiffuse(osg::Vec4(0.9f, 0.9f, 0.9f, 1));
    root->addChild(light.get());

    const double nl = 1.0 / std::sqrt(2.0);
    const osg::Vec3d halfway = osg::Vec3d(-nl, 0, nl + 1.0);
    const double nh = nl / halfway.length();  // n = (-1, 0, 0)
    const double highlight = 0.3 * std::pow(nh, 24.0);
    const double alpha = 1.0 - std::pow(1.0 - double(albedo.a()), 8.0);
    for (auto kind : {ReferenceOptions::Gradient::Exact, ReferenceOptions::Gradient::CentralDifferences}) {
        ReferenceOptions options;
        options.gradient = kind;
        const ReferenceImage img = renderReference(ReferenceScene::collect(*root), orthoFromPlusZ(16, 16.0), options);
        for (int c = 0; c < 3; ++c) {
            const double lit = double(albedo[c]) * (0.2 + 0.9 * nl) + 0.9 * highlight;
            EXPECT_NEAR(img.at(8, 8, c), lit * alpha, 1e-6) << "channel " << c;
        }
        // lighting_surface: the mix of the two by w = 1 - exp(-|g| / (0.05 window / spacing)),
        // |g| = 10 per unit over the window 0..255.
        node->settings.functions["Shading"] = "lighting_surface";
        const ReferenceImage surface = renderReference(ReferenceScene::collect(*root), orthoFromPlusZ(16, 16.0), options);
        const double w = -std::expm1(-10.0 / (0.05 * 255.0));
        for (int c = 0; c < 3; ++c) {
            const double lit = double(albedo[c]) * (0.2 + 0.9 * nl) + 0.9 * highlight;
            EXPECT_NEAR(surface.at(8, 8, c), ((1.0 - w) * double(albedo[c]) + w * lit) * alpha, 1e-6) << "surface " << c;
        }
        node->settings.functions["Shading"] = "lighting";
        options.lighting = false;
        const ReferenceImage unlit = renderReference(ReferenceScene::collect(*root), orthoFromPlusZ(16, 16.0), options);
        EXPECT_NEAR(unlit.at(8, 8, 0), double(albedo.r()) * alpha, 1e-6) << "lighting off: the TF colour";
    }
}

TEST(ReferenceRenderer, HenyeyGreensteinScalesEachLightByThePhaseFunction)
{
    // A homogeneous block lit by one directional light, no ambient: every sample's light is the
    // phase function at the angle between the light's travel and the view, so the image at g
    // over the image at g = 0 is (1 - g^2) / (1 + g^2 - 2 g cos)^(3/2).
    auto node = makeVolumeNode(constantVolume(VoxelType::UInt8, {8, 8, 8}, 100).get(),
                               constantTransferFunction(osg::Vec4(0.8f, 0.5f, 0.25f, 0.2f)).get());
    std::string error;
    ASSERT_TRUE(node->settings.set("ambient", "0", error)) << error;
    node->settings.functions["Shading"] = "lighting";
    node->settings.functions["Illumination"] = "henyey_greenstein";
    osg::ref_ptr<osg::Group> root = withNode(node);
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setDiffuse(osg::Vec4(1, 1, 1, 1));
    root->addChild(light.get());
    auto pixel = [&](double g, const osg::Vec4& towardsLight, int c) {
        node->settings.parameters["anisotropy"] = g;
        light->getLight()->setPosition(towardsLight);
        return renderReference(ReferenceScene::collect(*root), orthoFromPlusZ(8, 16.0)).at(4, 4, c);
    };
    // From the viewer (cos = -1: back-scattered) and from the side (cos = 0).
    for (const auto& [towards, cosTheta] : {std::pair{osg::Vec4(0, 0, 1, 0), -1.0}, std::pair{osg::Vec4(-1, 0, 0, 0), 0.0}})
        for (double g : {0.5, -0.5, 0.9}) {
            const double phase = (1 - g * g) / std::pow(1 + g * g - 2 * g * cosTheta, 1.5);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel(g, towards, c) / pixel(0.0, towards, c), phase, 1e-9) << g;
        }
}

TEST(ReferenceRenderer, NanVoxelsAreEmptyAndOpaqueOpacityStopsTheRay)
{
    auto nanNode = makeVolumeNode(constantVolume(VoxelType::Float32, {8, 8, 8}, std::nan("")).get(),
                                             constantTransferFunction(osg::Vec4(1, 1, 1, 0.5f)).get());
    EXPECT_EQ(renderReference(ReferenceScene::collect(*withNode(nanNode)), orthoFromPlusZ(4, 2.0)).at(2, 2, 3), 0.0);
    auto opaque = makeVolumeNode(constantVolume(VoxelType::UInt8, {8, 8, 8}, 10).get(),
                                            constantTransferFunction(osg::Vec4(0.25f, 0.5f, 0.75f, 1.0f)).get());
    const ReferenceImage img = renderReference(ReferenceScene::collect(*withNode(opaque)), orthoFromPlusZ(4, 2.0));
    EXPECT_EQ(img.at(2, 2, 3), 1.0);
    EXPECT_EQ(img.at(2, 2, 2), 0.75);
}

// Exact single-scattering shadows (Shadowing ray, ReferenceScene::Shadows::Exact).

/// Orthographic camera looking down -z at the origin, `w` x `h` world units, one pixel per unit.
ReferenceCamera orthoPixelPerUnit(int w, int h)
{
    ReferenceCamera c;
    c.width = w;
    c.height = h;
    c.view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 100), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    c.projection = osg::Matrixd::ortho(-w / 2.0, w / 2.0, -h / 2.0, h / 2.0, 1, 200);
    return c;
}

/// Lit by Lambert only (no ambient), shadows as `shadowing` says.
void litByLambert(VolumeNode& node, const char* shadowing)
{
    std::string error;
    ASSERT_TRUE(node.settings.set("ambient", "0", error)) << error;
    node.settings.functions["Shading"] = "lighting";
    node.settings.functions["Illumination"] = "lambert";
    node.settings.functions["Shadowing"] = shadowing;
}

osg::ref_ptr<osg::LightSource> lightAt(const osg::Vec4& position)
{
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(position);
    light->getLight()->setDiffuse(osg::Vec4(1, 1, 1, 1));
    return light;
}

/// 32 x 4 x 4 voxels along x: a lit block (voxels 0-7, values falling 200..130 along x, so its
/// normal is +x), a gap of zeros, a slab of 255 (voxels 16-23) when `slab`, zeros to the end.
/// The TF's opacity rises linearly from 0 at 0 to `a` at 255, in one colour.
osg::ref_ptr<VolumeNode> blockAndSlab(bool slab, double a)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt8, {32, 4, 4});
    for (std::size_t i = 0; i < v->voxelCount(); ++i) {
        const std::size_t x = i % 32;
        v->data()[i] = x < 8 ? std::uint8_t(200 - 10 * x) : (slab && x >= 16 && x < 24) ? 255 : 0;
    }
    v->dirty();
    auto tf = transferFunction(
        {{0.0, osg::Vec4(0.8f, 0.6f, 0.4f, 0.0f)}, {255.0, osg::Vec4(0.8f, 0.6f, 0.4f, float(a))}}, 0.0, 255.0);
    return makeVolumeNode(v.get(), tf.get());
}

TEST(ReferenceShadows, SlabBetweenLightAndBlockScalesItsLightByTheSlabsTransmittance)
{
    // A directional light exactly along +x: every shadow ray from the block (x < -8) crosses the
    // whole slab, so with the slab every lit sample's light is exp(-tau) times that without it
    // (the block shadowing itself alike), and so is each block pixel (no ambient). tau: 7 voxels
    // of opacity a (sigma = -ln(1 - a)) and two ramps of one voxel from 0 to a, each
    // integral_0^1 -ln(1 - a t) dt = (a + (1 - a) ln(1 - a)) / a.
    const double a = 0.3, fa = double(float(a));
    const double tau = 7.0 * -std::log1p(-fa) + 2.0 * (fa + (1.0 - fa) * std::log1p(-fa)) / fa;
    ReferenceOptions options;
    options.tolerance = 1e-6;
    auto render = [&](bool slab, const char* shadowing, ClipNode* clip = nullptr) {
        auto node = blockAndSlab(slab, a);
        litByLambert(*node, shadowing);
        osg::ref_ptr<osg::Group> root = withNode(node);
        root->addChild(lightAt(osg::Vec4(1, 0, 0, 0)).get());
        if (clip) root->addChild(clip);
        return renderReference(ReferenceScene::collect(*root), orthoPixelPerUnit(32, 4), options);
    };
    const ReferenceImage with = render(true, "ray"), without = render(false, "ray"), unshadowed = render(true, "null");
    EXPECT_EQ(with.unconverged, 0u);
    EXPECT_EQ(without.unconverged, 0u);
    for (int x = 0; x < 12; ++x) {  // pixel x sees voxel column x: the block and its edge
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(with.at(x, 2, c), std::exp(-tau) * without.at(x, 2, c), 1e-6) << "pixel " << x << ", " << c;
        EXPECT_EQ(with.at(x, 2, 3), without.at(x, 2, 3)) << "shadows change no opacity";
    }
    EXPECT_GT(without.at(3, 2, 0), 0.05) << "the block is lit";
    EXPECT_LT(without.at(3, 2, 0), unshadowed.at(3, 2, 0) * 0.9) << "and shadows itself";

    // A clip plane keeping x <= -4 removes the slab for the shadow rays too: the block is lit as
    // without it, exactly (a clipped point and an empty one add nothing alike).
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(-1, 0, 0, -4);
    const ReferenceImage clipped = render(true, "ray", plane.get());
    for (int x = 0; x < 12; ++x)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(clipped.at(x, 2, c), without.at(x, 2, c), 1e-12) << x << " " << c;
}

TEST(ReferenceShadows, PointLightInsideAHomogeneousMediumIsDimmedByExpOfSigmaTimesDistance)
{
    // A homogeneous medium (zero gradient: the normal is the view direction +z) lit by a point
    // light at (0, 0, zl) inside it: the sample at z on the ray at distance rho from the light's
    // axis gets the light attenuated by exp(-sigma r) over r = |sample - light| (up to the
    // light, not to the box), times Lambert's (zl - z) / r. The pixel is
    // c integral_{-8}^{zl} sigma exp(-sigma (8 - z)) (zl - z)/r exp(-sigma r) dz, found here by
    // Simpson's rule on 20000 intervals. Anisotropic spacing: sigma = -ln(1 - a) / smallest spacing.
    const double a = 0.1, fa = double(float(a)), zl = 2.0;
    const osg::Vec4 colour(0.9f, 0.5f, 0.3f, float(a));
    for (const osg::Vec3d spacing : {osg::Vec3d(1, 1, 1), osg::Vec3d(0.5, 1, 2)}) {
        const osg::Vec3i dims(int(16 / spacing.x()), int(16 / spacing.y()), int(16 / spacing.z()));
        auto node = makeVolumeNode(constantVolume(VoxelType::UInt8, dims, 50, spacing).get(),
                                   constantTransferFunction(colour).get());
        litByLambert(*node, "ray");
        osg::ref_ptr<osg::Group> root = withNode(node);
        root->addChild(lightAt(osg::Vec4(0, 0, zl, 1)).get());
        ReferenceOptions options;
        options.tolerance = 1e-7;
        const ReferenceImage img = renderReference(ReferenceScene::collect(*root), orthoFromPlusZ(4, 8.0), options);
        EXPECT_EQ(img.unconverged, 0u);
        const double sigma = -std::log1p(-fa) / std::min({spacing.x(), spacing.y(), spacing.z()});
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const double px = 2.0 * x - 3.0, py = 2.0 * y - 3.0, rho2 = px * px + py * py;
                auto f = [&](double z) {
                    const double r = std::sqrt(rho2 + (zl - z) * (zl - z));
                    return sigma * std::exp(-sigma * (8.0 - z)) * (zl - z) / r * std::exp(-sigma * r);
                };
                const int n = 20000;
                const double h = (zl + 8.0) / n;
                double sum = f(-8.0) + f(zl);
                for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * f(-8.0 + k * h);
                const double light = sum * h / 3.0;
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(img.at(x, y, c), double(colour[c]) * light, 1e-6) << x << "," << y << " channel " << c;
                EXPECT_NEAR(img.at(x, y, 3), -std::expm1(-16.0 * sigma), 1e-12);
            }
    }
}

TEST(ReferenceShadows, NoNanOrInfAlongAxesDiagonalsFacesOrWithTheLightInside)
{
    // Noise with NaN voxels and opaque values, a clip plane, zero-gradient regions, lights along
    // +x, along the diagonal, from -y, and two point lights inside (one on a voxel centre), seen
    // by pixels whose rays run exactly along the box's x faces (17 pixels over 17 units: centres
    // at x = -8 and 8) and by a perspective camera inside the volume.
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::Float32, {16, 16, 16});
    auto* values = reinterpret_cast<float*>(v->data());
    std::uint32_t seed = 7;
    for (std::size_t i = 0; i < v->voxelCount(); ++i) {
        seed = seed * 1664525u + 1013904223u;
        const std::uint32_t r = seed >> 24;
        values[i] = r < 8 ? std::nanf("") : (i / 256) < 4 ? 100.0f : float(r);  // z < 4: constant
    }
    v->dirty();
    auto tf = transferFunction({{0.0, osg::Vec4(1, 1, 1, 0)}, {100.0, osg::Vec4(0.5f, 0.7f, 0.9f, 0.2f)},
                                {240.0, osg::Vec4(1, 0.5f, 0.2f, 0.6f)}, {250.0, osg::Vec4(1, 1, 1, 1)}},
                               0.0, 255.0);
    auto node = makeVolumeNode(v.get(), tf.get());
    node->settings.functions["Shading"] = "lighting";
    node->settings.functions["Illumination"] = "blinn_phong";
    node->settings.functions["Shadowing"] = "ray";
    osg::ref_ptr<osg::Group> root = withNode(node);
    for (const osg::Vec4& p : {osg::Vec4(1, 0, 0, 0), osg::Vec4(1, 1, 1, 0), osg::Vec4(0, -1, 0, 0),
                               osg::Vec4(0.5f, 0.5f, 0.5f, 1), osg::Vec4(-3, 2, 7.9f, 1)})
        root->addChild(lightAt(p).get());
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(osg::Vec3d(1, 1, 1), osg::Vec3d(2, 0, 0));  // keeps x + y + z >= 2
    root->addChild(plane.get());

    ReferenceCamera inside;
    inside.width = inside.height = 9;
    inside.view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, 0), osg::Vec3d(1, 1, 1), osg::Vec3d(0, 0, 1));
    inside.projection = osg::Matrixd::perspective(60, 1, 0.5, 100);
    ReferenceOptions options;
    options.tolerance = 1e-2;
    options.finestStep = 1.0 / 64.0;  // noise: bounded work, convergence not the point here
    for (const ReferenceCamera& camera : {orthoPixelPerUnit(17, 17), inside}) {
        const ReferenceScene scene = ReferenceScene::collect(*root);
        const ReferenceImage img = renderReference(scene, camera, options);
        double sum = 0.0;
        for (double value : img.rgba) {
            ASSERT_TRUE(std::isfinite(value));
            EXPECT_GE(value, 0.0);
            sum += value;
        }
        node->settings.functions["Shadowing"] = "null";
        const ReferenceImage unshadowed = renderReference(ReferenceScene::collect(*root), camera, options);
        node->settings.functions["Shadowing"] = "ray";
        double unshadowedSum = 0.0;
        for (double value : unshadowed.rgba) unshadowedSum += value;
        EXPECT_LT(sum, unshadowedSum) << "shadows darken";
        EXPECT_GT(sum, 0.0);
    }
}

TEST(ReferenceShadows, NullShadowingIsTheUnshadowedImageBitForBitAndUndeclaredOnesAreRefused)
{
    // Shadowing unset, "null" or ReferenceScene::Shadows::None: one and the same image, bit for
    // bit (the unshadowed integral this reference computed before shadows existed).
    auto node = blockAndSlab(true, 0.3);
    litByLambert(*node, "null");
    node->settings.functions.erase("Shadowing");
    osg::ref_ptr<osg::Group> root = withNode(node);
    root->addChild(lightAt(osg::Vec4(1, 0.3f, 0.5f, 0)).get());
    root->addChild(lightAt(osg::Vec4(-4, 1, 3, 1)).get());
    const ReferenceCamera camera = orthoPixelPerUnit(32, 4);
    const ReferenceImage unset = renderReference(ReferenceScene::collect(*root), camera);
    node->settings.functions["Shadowing"] = "null";
    EXPECT_EQ(renderReference(ReferenceScene::collect(*root), camera).rgba, unset.rgba);
    node->settings.functions["Shadowing"] = "ray";
    ReferenceScene forcedNone = ReferenceScene::collect(*root);
    forcedNone.volumes[0].shadows = ReferenceScene::Shadows::None;
    EXPECT_EQ(renderReference(forcedNone, camera).rgba, unset.rgba);
    const ReferenceImage ray = renderReference(ReferenceScene::collect(*root), camera);
    EXPECT_NE(ray.rgba, unset.rgba);

    // An approximation is measured against the model it declares: the light volume's is the exact
    // shadows, the image of ray.
    node->settings.functions["Shadowing"] = "light_volume";
    EXPECT_EQ(renderReference(ReferenceScene::collect(*root), camera).rgba, ray.rgba);
    // A Shadowing that declares no model is refused by name, unless the scene says which shadows
    // it approximates.
    node->settings.functions["Shadowing"] = "undeclared_shadows";
    try {
        renderReference(ReferenceScene::collect(*root), camera);
        ADD_FAILURE() << "a Shadowing without a model was not refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("undeclared_shadows"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("declares none"), std::string::npos) << e.what();
    }
    ReferenceScene approximating = ReferenceScene::collect(*root);
    approximating.volumes[0].shadows = ReferenceScene::Shadows::Exact;
    EXPECT_EQ(renderReference(approximating, camera).rgba, ray.rgba);
    // Unlit (lighting off), the choice does not matter.
    ReferenceOptions unlit;
    unlit.lighting = false;
    EXPECT_NO_THROW(renderReference(ReferenceScene::collect(*root), camera, unlit));
}


/// `v` through `tf` with exact shadows (Shadowing ray), lit by ambient light only (`ambient`,
/// and a black light from +z), its ambient term scaled by the occlusion when asked (cone_ao).
ReferenceScene ambientOnly(Volume* v, TransferFunction* tf, double ambient, bool occlusion)
{
    auto node = makeVolumeNode(v, tf);
    litByLambert(*node, "ray");
    node->settings.parameters["ambient"] = double(ambient);
    osg::ref_ptr<osg::Group> root = withNode(node);
    osg::ref_ptr<osg::LightSource> light = lightAt(osg::Vec4(0, 0, 1, 0));
    light->getLight()->setDiffuse(osg::Vec4(0, 0, 0, 1));
    root->addChild(light.get());
    ReferenceScene content = ReferenceScene::collect(*root);
    content.volumes[0].occlusion = occlusion;
    return content;
}

TEST(ReferenceShadows, AmbientOcclusionDeepInAHomogeneousMediumIsExpMinusSigmaTimesItsReach)
{
    // A 40^3 block as opaque everywhere (alpha 0.08 per voxel), white only in the layer 20-21
    // voxels below the face the camera looks at; lit by ambient light only (a black light). Every
    // direction over the layer's hemisphere (reach 8 voxels, from half a voxel out) stays inside
    // the block, so cone_ao's occlusion there is exp(-sigma 7.5) and scales the layer's light.
    const int n = 40;
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::UInt8, {n, n, n});
    for (int z = 0; z < n; ++z) std::fill_n(v->data() + std::size_t(z) * n * n, std::size_t(n) * n, z == n - 21 ? 200 : 100);
    v->dirty();
    const float a = 0.08f;
    auto tf = transferFunction({{150.0, osg::Vec4(0, 0, 0, a)}, {200.0, osg::Vec4(1, 1, 1, a)}}, 0.0, 255.0);
    ReferenceOptions options;
    options.tolerance = 1e-5;
    auto render = [&](bool occlusion) {  // exact shadows, with or without ambient occlusion (cone, cone_ao)
        return renderReference(ambientOnly(v.get(), tf.get(), 0.5, occlusion), orthoPixelPerUnit(1, 1), options);
    };
    const ReferenceImage open = render(false), occluded = render(true);
    EXPECT_EQ(occluded.unconverged, 0u);
    ASSERT_GT(open.at(0, 0, 0), 1e-4);
    const double sigma = -std::log1p(-double(a));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(occluded.at(0, 0, c) / open.at(0, 0, c), std::exp(-sigma * 7.5), 1e-4) << c;
    EXPECT_EQ(occluded.at(0, 0, 3), open.at(0, 0, 3)) << "occlusion changes light, not coverage";
}

TEST(ReferenceShadows, AmbientOcclusionsFixedQuadratureIsCloseToAFinerOneAndLetsViewRaysConverge)
{
    // Blobs in a 24^3 volume, lit by ambient light only: each pixel is the ambient term scaled
    // by the occlusion along its ray. The default quadrature (12^2 directions, quarter-voxel
    // steps) against 4x the directions (24^2) at 1/8-voxel steps: the error it states. Before this
    // quadrature was fixed, the per-sample adaptive one kept view rays from converging.
    const int n = 24;
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(VoxelType::Float32, {n, n, n});
    auto* values = reinterpret_cast<float*>(v->data());
    const osg::Vec3d centres[] = {{6, 8, 12}, {15, 14, 10}, {11, 17, 17}, {17, 6, 15}};
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                double sum = 0.0;
                for (const osg::Vec3d& c : centres) sum += std::exp(-(osg::Vec3d(x, y, z) - c).length2() / 18.0);
                values[(std::size_t(z) * n + y) * n + x] = float(200.0 * std::min(sum, 1.0));
            }
    v->dirty();
    auto tf = transferFunction({{20.0, osg::Vec4(1, 1, 1, 0)}, {120.0, osg::Vec4(1, 0.8f, 0.6f, 0.15f)},
                                {200.0, osg::Vec4(1, 1, 1, 0.3f)}}, 0.0, 255.0);
    auto render = [&](bool occlusion, int directions, double step) {
        ReferenceOptions options;
        options.tolerance = 1e-3;
        options.occlusionDirections = directions;
        options.occlusionStep = step;
        return renderReference(ambientOnly(v.get(), tf.get(), 1.0, occlusion), orthoFromPlusZ(5, 20.0), options);
    };
    const ReferenceImage open = render(false, 12, 0.25), coarse = render(true, 12, 0.25), fine = render(true, 24, 0.125);
    EXPECT_EQ(coarse.unconverged, 0u);
    EXPECT_EQ(fine.unconverged, 0u);
    double largest = 0.0, effect = 0.0;
    for (std::size_t i = 0; i < coarse.rgba.size(); ++i) {
        largest = std::max(largest, std::abs(coarse.rgba[i] - fine.rgba[i]));
        effect = std::max(effect, std::abs(open.rgba[i] - fine.rgba[i]));
    }
    std::printf("occlusion's effect %.4f, default quadrature against a finer one: %.5f\n", effect, largest);
    EXPECT_GT(effect, 0.05) << "the blobs occlude each other";
    EXPECT_LT(largest, 2e-3);
}

}  // namespace
}  // namespace volren::test
