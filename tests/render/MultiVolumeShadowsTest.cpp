// Shadows in a multi-volume set: overlapping volumes marched along one ray, each lit sample
// shadowed by its own volume's medium (as the reference defines it), with every shadowing
// method, the light volume's and the cones' built per member. Two overlapping homogeneous
// boxes lit by a headlight (Lambert, zero gradients: every sample's normal faces the light):
// a sample of box m at distance s_m below m's face towards the light emits c_m exp(-sigma_m s_m).
// The expectation is that integral along the view ray, summed numerically at 1/64 unit.
#include "FortyUnitView.h"
#include "RenderFixture.h"
#include "TestData.h"

#include <osg/LightSource>
#include <osg/Matrixd>
#include <osg/MatrixTransform>

#include <cmath>
#include <functional>

namespace volren::test {
namespace {

struct Box
{
    osg::Vec3d colour;
    double alpha;    ///< TF opacity per unit length (spacing 1)
    double zMin, zMax;  ///< extent along the view ray (and the light), world units
    double sigma() const { return -std::log1p(-alpha); }
    bool holds(double z) const { return z > zMin && z < zMax; }
};

/// Colour and opacity of the view ray from +z through `boxes` (each lit through its own medium
/// when `shadows`), by the midpoint rule at 1/64 unit.
osg::Vec4d expected(const std::vector<Box>& boxes, bool shadows)
{
    const double h = 1.0 / 64.0;
    double top = -1e30, bottom = 1e30;
    for (const Box& b : boxes) top = std::max(top, b.zMax), bottom = std::min(bottom, b.zMin);
    osg::Vec3d colour;
    double depth = 0.0;
    for (double z = top - 0.5 * h; z > bottom; z -= h) {
        double sigma = 0.0;
        osg::Vec3d emission;
        for (const Box& b : boxes) {
            if (!b.holds(z)) continue;
            sigma += b.sigma();
            emission += b.colour * (b.sigma() * (shadows ? std::exp(-b.sigma() * (b.zMax - z)) : 1.0));
        }
        if (sigma <= 0.0) continue;
        // Within the step the medium is homogeneous: emission / sigma of the opacity gained.
        colour += emission * (std::exp(-depth) * -std::expm1(-sigma * h) / sigma);
        depth += sigma * h;
    }
    return osg::Vec4d(colour, -std::expm1(-depth));
}

class MultiVolumeShadows : public RenderFixture
{
protected:
    // Red A: a 16-unit cube centred at (0, 0, -4); blue B: centred at (4, 0, 4). The ray at
    // x = y = 0.5 crosses B alone for z in [4, 12], both in [-4, 4], A alone in [-12, -4].
    const Box a{{1.0, 0.1, 0.1}, 0.08, -12.0, 4.0};
    const Box b{{0.1, 0.2, 1.0}, 0.04, -4.0, 12.0};

    /// Both boxes lit by a light at `light` with `shadowing` (light volume at full resolution);
    /// black (absorbing only) when asked.
    osg::ref_ptr<VolumeScene> scene(const std::string& shadowing, const osg::Vec4& light = {0, 0, 1, 0},
                                    bool black = false) const
    {
        osg::ref_ptr<VolumeScene> s = new VolumeScene;
        for (const Box* box : {&a, &b}) {
            const osg::Vec3 colour = black ? osg::Vec3() : osg::Vec3(box->colour);
            auto node = volumeNode(constantVolume(VoxelType::UInt8, {16, 16, 16}, 100).get(),
                                   constantTransferFunction(osg::Vec4(colour, float(box->alpha))).get());
            node->setName(box == &a ? "A" : "B");
            node->settings.functions["Shading"] = "lighting";
            node->settings.functions["Illumination"] = "lambert";
            node->settings.functions["Shadowing"] = shadowing;
            node->settings.parameters["ambient"] = 0.0;
            node->settings.earlyTerminationThreshold = 1.0;
            node->settings.sampleDistanceFactor = 0.5;
            node->settings.parameters["lightVolumeScale"] = 1.0;
            node->settings.parameters["coneAngle"] = 0.5;       // narrow: the chain's level 0 all the way
            node->settings.parameters["coneStart"] = 0.0;       // the shadow from the sample itself on
            node->settings.parameters["coneStepGrowth"] = 0.5;  // half-voxel steps, as the shadow rays'
            osg::ref_ptr<osg::MatrixTransform> t =
                new osg::MatrixTransform(osg::Matrix::translate(box == &a ? osg::Vec3(0, 0, -4) : osg::Vec3(4, 0, 4)));
            t->addChild(node.get());
            s->addChild(t.get());
        }
        osg::ref_ptr<osg::LightSource> source = new osg::LightSource;
        source->getLight()->setLightNum(0);
        source->getLight()->setPosition(light);
        source->getLight()->setDiffuse(osg::Vec4(1, 1, 1, 1));  // OSG's default is 0.8
        s->addChild(source.get());
        return s;
    }
};

TEST_F(MultiVolumeShadows, EveryMethodShadowsEachMemberByItsOwnMediumAlongOneRay)
{
    // Without shadows the expectation is the closed form of the MultiVolume tests' media.
    const osg::Vec4d lit = expected({a, b}, false), shadowed = expected({a, b}, true);
    double difference = 0.0;
    for (int c = 0; c < 3; ++c) difference = std::max(difference, std::abs(lit[c] - shadowed[c]));
    ASSERT_GT(difference, 0.05) << "the shadows must matter here";

    // Each method's error on homogeneous media: shadow rays integrate them exactly; narrow cones
    // from the sample on too, but for their half-float chain and its extinction falling to half
    // at a face (the border is empty), which loses sigma/8 of a voxel's optical depth on the way
    // out (the image of a single volume is 0.0036 brighter in red); the light volume
    // interpolates exp() between texel centres.
    const std::vector<std::pair<std::string, double>> methods = {
        {"null", 2e-3}, {"ray", 2e-3}, {"light_volume", 4e-3}, {"cone", 5e-3}, {"cone_ao", 5e-3}};
    for (const auto& [method, tolerance] : methods) {
        osg::ref_ptr<VolumeScene> s = scene(method);
        const Pixels p = renderOrthoFromPlusZ(s.get(), 40, 40, 40.0);
        const std::vector<std::string> keys = s->compositionKeys();
        ASSERT_EQ(keys.size(), 1u) << method << ": one program for the set";
        EXPECT_NE(keys.front().find("members{"), std::string::npos) << keys.front();
        EXPECT_NE(keys.front().find("Shadowing=" + method), std::string::npos) << keys.front();
        const bool shadows = method != "null";
        expectNear(pixelAt(p, 0.5, 0.5), expected({a, b}, shadows), tolerance, method + ": B, then both, then A");
        expectNear(pixelAt(p, -6.5, 0.5), expected({a}, shadows), tolerance, method + ": A alone");
        expectNear(pixelAt(p, 10.5, 0.5), expected({b}, shadows), tolerance, method + ": B alone");
        if (method == "light_volume" || method == "cone") {
            const std::vector<BuiltVolumeStatistics> built = s->builtVolumeStatistics();
            ASSERT_EQ(built.size(), 2u) << method << ": one built volume per member";
            for (const BuiltVolumeStatistics& v : built) EXPECT_EQ(v.builds, 1u) << method << " of " << v.node;
        }
    }
}

TEST_F(MultiVolumeShadows, MovingTheLightRebuildsEachMembersLightVolume)
{
    // The light turned 45 degrees towards +x: each sample is shadowed by its own medium along
    // the diagonal out of its box. Shadow rays are the exact method to match there.
    const osg::Vec4 diagonal(float(std::sqrt(0.5)), 0.0f, float(std::sqrt(0.5)), 0.0f);
    osg::ref_ptr<VolumeScene> s = scene("light_volume");
    renderOrthoFromPlusZ(s.get(), 40, 40, 40.0);
    osg::LightSource* source = nullptr;
    for (unsigned int i = 0; i < s->getNumChildren(); ++i)
        if (auto* l = dynamic_cast<osg::LightSource*>(s->getChild(i))) source = l;
    ASSERT_NE(source, nullptr);
    source->getLight()->setPosition(diagonal);
    const Pixels p = renderOrthoFromPlusZ(s.get(), 40, 40, 40.0);
    const std::vector<BuiltVolumeStatistics> built = s->builtVolumeStatistics();
    ASSERT_EQ(built.size(), 2u);
    for (const BuiltVolumeStatistics& v : built) EXPECT_EQ(v.builds, 2u) << v.node;
    osg::ref_ptr<VolumeScene> rays = scene("ray", diagonal), none = scene("null", diagonal);
    const Pixels exact = renderOrthoFromPlusZ(rays.get(), 40, 40, 40.0);
    const Pixels unshadowed = renderOrthoFromPlusZ(none.get(), 40, 40, 40.0);
    for (double x : {-6.5, 0.5, 2.5, 4.5}) {
        const std::string where = "x = " + std::to_string(x);
        expectNear(pixelAt(p, x, 0.5), osg::Vec4d(pixelAt(exact, x, 0.5)), 4e-3, where);
        EXPECT_GT(pixelAt(unshadowed, x, 0.5).r() + pixelAt(unshadowed, x, 0.5).b() -
                      pixelAt(exact, x, 0.5).r() - pixelAt(exact, x, 0.5).b(), 0.04)
            << where << ": the shadows must matter here";
    }
}

TEST_F(MultiVolumeShadows, OpaqueGeometryAndTheSetShadowEachOther)
{
    // An opaque square in the plane y = 12 over x < 0, seen edge-on, and the light from above and
    // in front (0, 1, 1): every way from a sample at x < 0 to the light crosses the square, none
    // from x > 0 does. With no ambient light the members' samples there go black (their coverage
    // stays); the rest is the image without the square.
    const osg::Vec4 light(0, 1, 1, 0);
    osg::ref_ptr<osg::MatrixTransform> wall = new osg::MatrixTransform(
        osg::Matrixd::scale(10, 30, 1) * osg::Matrixd::rotate(osg::PI_2, osg::X_AXIS) * osg::Matrixd::translate(-10, 12, 10));
    wall->addChild(flatSquare({0, 0, 0}, 1.0f, {0.2f, 0.8f, 0.2f, 1.0f}).get());
    for (const char* method : {"ray", "light_volume", "cone", "cone_ao"}) {
        SCOPED_TRACE(method);
        osg::ref_ptr<VolumeScene> open = scene(method, light);
        osg::ref_ptr<osg::Group> bound = new osg::Group;  // frames the view as the wall does
        bound->setInitialBound(wall->getBound());
        open->addChild(bound.get());
        const Pixels without = renderOrthoFromPlusZ(open.get(), 40, 40, 40.0);
        osg::ref_ptr<VolumeScene> walled = scene(method, light);
        walled->addChild(wall.get());
        const Pixels with = renderOrthoFromPlusZ(walled.get(), 40, 40, 40.0);
        const std::vector<std::string> keys = walled->compositionKeys();
        ASSERT_EQ(keys.size(), 1u) << "one program for the set";
        EXPECT_NE(keys.front().find("geometryShadows=1;"), std::string::npos) << keys.front();
        for (double x : {-6.5, -2.5, 0.5, 6.5, 10.5}) {
            const osg::Vec4 &was = pixelAt(without, x, 0.5), &is = pixelAt(with, x, 0.5);
            ASSERT_GT(was.r() + was.b(), 0.05f) << x;
            EXPECT_NEAR(is.a(), was.a(), 1e-6) << "coverage at x = " << x;
            for (int c = 0; c < 3; ++c) {
                if (x < 0.0) EXPECT_LT(is[c], 1e-4f) << "x = " << x;
                else EXPECT_NEAR(is[c], was[c], 1e-5) << "x = " << x;
            }
        }
    }

    // The other way: black members in front of a white square at z = -14, the light along the
    // view. The light volume darkens each square pixel by the product of the members'
    // transmittances to the light (by the geometry pass of each); shadow rays leave the square
    // alone (documented).
    for (const char* method : {"light_volume", "ray"}) {
        SCOPED_TRACE(method);
        osg::ref_ptr<VolumeScene> s = scene(method, {0, 0, 1, 0}, true);
        s->addChild(flatSquare({0, 0, -14}, 19.0f, {1, 1, 1, 1}).get());
        const Pixels img = renderOrthoFromPlusZ(s.get(), 40, 40, 40.0);
        const bool shadowsSquare = std::string(method) == "light_volume";
        for (const auto& [x, depth] : std::vector<std::pair<double, double>>{
                 {-6.5, 16.0 * a.sigma()}, {0.5, 16.0 * (a.sigma() + b.sigma())}, {10.5, 16.0 * b.sigma()}, {14.5, 0.0}}) {
            const double want = std::exp(-depth) * (shadowsSquare ? std::exp(-depth) : 1.0);
            // Within 1% per member crossed: the single-volume bound (MixedShadows); each member's
            // light volume reads about 0.6% dark here.
            EXPECT_NEAR(pixelAt(img, x, 0.5).g(), want, 0.01 * want * (x == 0.5 ? 2 : 1)) << "x = " << x;
        }
    }
}

}  // namespace
}  // namespace volren::test
