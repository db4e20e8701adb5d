// Overlapping volumes are marched as one ray through all of them (a multi-volume set, one
// program): where they overlap their media add. Closed forms of the emission-absorption
// integral through two overlapping homogeneous boxes, with and without an opaque square inside
// the overlap; and the scene analysis that decides which volumes form a set.
#include "FortyUnitView.h"
#include "RenderFixture.h"
#include "TestData.h"

#include <osg/MatrixTransform>
#include <osg/Notify>

#include <algorithm>
#include <cmath>

namespace volren::test {
namespace {

struct Medium
{
    osg::Vec3d colour;
    double alpha;  // TF opacity per unit length (spacing 1)
    double sigma() const { return -std::log1p(-alpha); }
};

/// Front-to-back emission-absorption through segments of (length, media present).
osg::Vec4d integrate(const std::vector<std::pair<double, std::vector<Medium>>>& segments, const osg::Vec4d& behind = {})
{
    osg::Vec3d colour;
    double transmittance = 1.0;
    for (const auto& [length, media] : segments) {
        double sigma = 0.0;
        osg::Vec3d emission;
        for (const Medium& m : media) {
            sigma += m.sigma();
            emission += m.colour * m.sigma();
        }
        if (sigma <= 0.0) continue;
        const double a = -std::expm1(-sigma * length);
        colour += emission * (transmittance * a / sigma);
        transmittance *= 1.0 - a;
    }
    colour += osg::Vec3d(behind.x(), behind.y(), behind.z()) * transmittance * behind.w();
    return osg::Vec4d(colour, 1.0 - transmittance * (1.0 - behind.w()));
}

osg::ref_ptr<osg::MatrixTransform> placed(osg::Node* child, const osg::Vec3d& at)
{
    osg::ref_ptr<osg::MatrixTransform> t = new osg::MatrixTransform(osg::Matrix::translate(at));
    t->addChild(child);
    return t;
}

class MultiVolume : public RenderFixture
{
protected:
    // Red medium A: a 16-unit cube centred at (0, 0, -4); blue medium B: centred at (4, 0, 4).
    // Seen from +z, the ray at x = y = 0.5 crosses B alone for z in [4, 12], both in [-4, 4] and
    // A alone in [-12, -4]; the ray at x = -6 crosses A alone.
    const Medium a{{1.0, 0.1, 0.1}, 0.08};
    const Medium b{{0.1, 0.2, 1.0}, 0.04};

    osg::ref_ptr<VolumeScene> twoMedia(const std::string& traversalOfB = "")
    {
        osg::ref_ptr<VolumeScene> scene = new VolumeScene;
        auto nodeA = volumeNode(constantVolume(VoxelType::UInt8, {16, 16, 16}, 100).get(),
                                constantTransferFunction(osg::Vec4(osg::Vec3(a.colour), float(a.alpha))).get());
        auto nodeB = volumeNode(constantVolume(VoxelType::UInt8, {16, 16, 16}, 100).get(),
                                constantTransferFunction(osg::Vec4(osg::Vec3(b.colour), float(b.alpha))).get());
        nodeA->setName("A");
        nodeB->setName("B");
        std::string error;
        for (VolumeNode* n : {nodeA.get(), nodeB.get()}) {
            EXPECT_TRUE(n->settings.set("earlyTermination", "1", error)) << error;
            EXPECT_TRUE(n->settings.set("samplerate", "1", error)) << error;
        }
        if (!traversalOfB.empty()) {
            EXPECT_TRUE(nodeB->settings.set("traversal", traversalOfB, error)) << error;
        }
        scene->addChild(placed(nodeA.get(), {0, 0, -4}));
        scene->addChild(placed(nodeB.get(), {4, 0, 4}));
        return scene;
    }
};

TEST_F(MultiVolume, OverlappingMediaAddAlongOneRay)
{
    osg::ref_ptr<VolumeScene> scene = twoMedia();
    const Pixels p = renderOrthoFromPlusZ(scene.get(), 40, 40, 40.0);

    const osg::Vec4d both = integrate({{8.0, {b}}, {8.0, {a, b}}, {8.0, {a}}});
    expectNear(pixelAt(p, 0.5, 0.5), both, 2e-3, "B, then A and B, then A");
    expectNear(pixelAt(p, -6.5, 0.5), integrate({{16.0, {a}}}), 2e-3, "A alone");
    expectNear(pixelAt(p, 10.5, 0.5), integrate({{16.0, {b}}}), 2e-3, "B alone");

    // Boxes drawn one after another (B's whole integral over A's) differ from the sum of media:
    // this scene tells the two apart (by 0.047 in red and blue, 20 times the tolerance).
    const osg::Vec4d bAlone = integrate({{16.0, {b}}}), aAlone = integrate({{16.0, {a}}});
    const osg::Vec4d boxByBox = bAlone + aAlone * (1.0 - bAlone.w());
    double difference = 0.0;
    for (int c = 0; c < 4; ++c) difference = std::max(difference, std::abs(boxByBox[c] - both[c]));
    EXPECT_GT(difference, 0.04);

    const std::vector<std::string> keys = scene->compositionKeys();
    ASSERT_EQ(keys.size(), 1u) << "one program for the set";
    EXPECT_NE(keys.front().find("RayTraversal=sum_of_media"), std::string::npos) << keys.front();
    EXPECT_NE(keys.front().find("members{"), std::string::npos) << keys.front();
    const auto programs = scene->programs();
    ASSERT_EQ(programs.size(), 1u);
    EXPECT_EQ(programs.front().first, "A + B");
}

TEST_F(MultiVolume, OpaqueSquareInsideTheOverlapIsAttenuatedByBothMediaInFrontOfIt)
{
    osg::ref_ptr<VolumeScene> scene = twoMedia();
    scene->addChild(flatSquare({0, 0, 0}, 3.0f, osg::Vec4(1, 1, 1, 1)));
    const Pixels p = renderOrthoFromPlusZ(scene.get(), 40, 40, 40.0);
    expectNear(pixelAt(p, 0.5, 0.5), integrate({{8.0, {b}}, {4.0, {a, b}}}, {1, 1, 1, 1}), 2e-3,
               "B, then 4 units of A and B, then the white square");
    expectNear(pixelAt(p, -6.5, 0.5), integrate({{16.0, {a}}}), 2e-3, "A alone, beside the square");
    const std::vector<std::string> keys = scene->compositionKeys();
    ASSERT_EQ(keys.size(), 1u);
    EXPECT_NE(keys.front().find("ClipRay=[depth];RayTraversal=sum_of_media"), std::string::npos) << keys.front();
}

TEST_F(MultiVolume, CameraInsideTheOverlapMarchesOnlyWhatLiesAhead)
{
    // Perspective camera at (0.5, 0.5, 0) looking down -z: its centre ray crosses 4 units of
    // both media and then 8 of A alone.
    osg::ref_ptr<VolumeScene> scene = twoMedia();
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0.5, 0.5, 0.0), osg::Vec3d(0.5, 0.5, -1.0), osg::Vec3d(0, 1, 0));
    const Pixels p = render(scene.get(), 41, 41, view, osg::Matrixd::perspective(10.0, 1.0, 0.01, 100.0));
    expectNear(p.at(20, 20), integrate({{4.0, {a, b}}, {8.0, {a}}}), 3e-3, "from inside the overlap");
}

TEST_F(MultiVolume, VolumesOneBehindTheOtherAreCompositedFrontOverBack)
{
    // B moved behind A along the view (boxes 4 units apart): two programs, drawn back to front,
    // whichever comes first in the scene; the closed form is A's integral over B's.
    for (const bool bFirst : {false, true}) {
        osg::ref_ptr<VolumeScene> scene = twoMedia();
        auto* tb = static_cast<osg::MatrixTransform*>(scene->getChild(1));
        tb->setMatrix(osg::Matrix::translate(0, 0, -24));
        if (bFirst) {
            osg::ref_ptr<osg::Node> b = tb;
            scene->removeChild(b.get());
            scene->insertChild(0, b.get());
        }
        const Pixels p = renderOrthoFromPlusZ(scene.get(), 40, 40, 40.0);
        EXPECT_EQ(scene->programs().size(), 2u);
        expectNear(pixelAt(p, 0.5, 0.5), integrate({{16.0, {a}}, {4.0, {}}, {16.0, {b}}}), 2e-3,
                   bFirst ? "B first in the scene" : "A first in the scene");
    }
}

TEST_F(MultiVolume, VolumesApartOrWithOtherTraversalsAreDrawnOneByOne)
{
    osg::ref_ptr<VolumeScene> apart = twoMedia();
    static_cast<osg::MatrixTransform*>(apart->getChild(1))->setMatrix(osg::Matrix::translate(40, 0, 0));
    renderOrthoFromPlusZ(apart.get(), 40, 40, 40.0);
    std::vector<std::string> keys = apart->compositionKeys();
    ASSERT_EQ(keys.size(), 1u) << "both volumes use the same single-volume program";
    EXPECT_EQ(keys.front().find("members{"), std::string::npos) << keys.front();
    EXPECT_EQ(apart->programs().size(), 2u);

    // An overlapping MIP cannot share an emission-absorption ray: drawn box by box, with a warning.
    osg::ref_ptr<VolumeScene> mixed = twoMedia("mip");
    const osg::NotifySeverity level = osg::getNotifyLevel();
    osg::setNotifyLevel(osg::FATAL);  // the expected warning stays out of the test log
    const Pixels p = renderOrthoFromPlusZ(mixed.get(), 40, 40, 40.0);
    osg::setNotifyLevel(level);
    keys = mixed->compositionKeys();
    ASSERT_EQ(keys.size(), 2u);
    for (const std::string& key : keys) EXPECT_EQ(key.find("members{"), std::string::npos) << key;
    expectNear(pixelAt(p, -6.5, 0.5), integrate({{16.0, {a}}}), 2e-3, "A alone still exact");
}

}  // namespace
}  // namespace volren::test
