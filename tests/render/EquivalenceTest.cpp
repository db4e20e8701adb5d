// Equivalences that must hold exactly (or, for jitter, up to noise of known size).
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipPlaneNode.h>

#include <osg/LightSource>

#include <cmath>
#include <map>
#include <cstring>

namespace volren::test {
namespace {

class Equivalence : public RenderFixture
{
protected:
    /// A lumpy float volume (20 x 16 x 12, spacing 1,1,1.5) with a warm TF.
    static osg::ref_ptr<VolumeNode> lumpy()
    {
        osg::ref_ptr<Volume> volume = new Volume;
        volume->allocate(VoxelType::Float32, {20, 16, 12});
        volume->setSpacing({1.0, 1.0, 1.5});
        auto* v = reinterpret_cast<float*>(volume->data());
        for (int z = 0; z < 12; ++z)
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 20; ++x)
                    v[x + 20 * (y + 16 * z)] = float(0.5 + 0.5 * std::sin(x * 0.6) * std::cos(y * 0.45 + z * 0.3));
        volume->dirty();
        osg::ref_ptr<TransferFunction> tf = new TransferFunction;
        tf->setPoint(0.2, osg::Vec4(0.2f, 0.1f, 0.0f, 0.0f));
        tf->setPoint(1.0, osg::Vec4(1.0f, 0.9f, 0.7f, 0.35f));
        return volumeNode(volume.get(), tf.get(), false);
    }

    static Pixels view(osg::Node* scene)
    {
        const osg::Matrixd v = osg::Matrixd::lookAt(osg::Vec3d(25, -30, 20), osg::Vec3d(), osg::Vec3d(0, 0, 1));
        return render(scene, 48, 40, v, osg::Matrixd::perspective(35, 1.2, 1, 200), osg::Vec3(0.1f, 0.2f, 0.3f));
    }

    static bool identical(const Pixels& a, const Pixels& b)
    {
        return a.rgba.size() == b.rgba.size() &&
               std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(osg::Vec4)) == 0;
    }

    static int covered(const Pixels& p)
    {
        int n = 0;
        for (const osg::Vec4& c : p.rgba) n += c.a() > 0.0f;
        return n;
    }
};

TEST_F(Equivalence, NullIlluminationEqualsTheSceneWithoutLights)
{
    osg::ref_ptr<VolumeNode> node = lumpy();
    osg::ref_ptr<VolumeScene> dark = new VolumeScene;
    dark->addChild(node.get());
    const Pixels withoutLights = view(dark.get());

    osg::ref_ptr<VolumeScene> lit = new VolumeScene;
    lit->addChild(node.get());
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(0, 0, 1, 0));
    lit->addChild(light.get());
    const Pixels litImage = view(lit.get());
    EXPECT_FALSE(identical(litImage, withoutLights)) << "the light must change the image";

    node->settings.forceNull.insert("Illumination");
    const Pixels nullIllumination = view(lit.get());
    EXPECT_TRUE(identical(nullIllumination, withoutLights));
    EXPECT_GT(covered(withoutLights), 400);
}

TEST_F(Equivalence, TwoCoincidentPlanesEqualOnePlane)
{
    osg::ref_ptr<VolumeNode> node = lumpy();
    auto planeNode = [] {
        osg::ref_ptr<ClipPlaneNode> p = new ClipPlaneNode;
        p->plane.set(osg::Vec3d(0.6, 0.8, 0.0), osg::Vec3d(1.0, 0.5, 0.0));
        return p;
    };
    osg::ref_ptr<VolumeScene> one = new VolumeScene;
    one->addChild(node.get());
    one->addChild(planeNode().get());
    const Pixels single = view(one.get());
    EXPECT_NE(one->compositionKeys()[0].find("ClipRay=[plane];"), std::string::npos);

    osg::ref_ptr<VolumeScene> two = new VolumeScene;
    two->addChild(node.get());
    two->addChild(planeNode().get());
    two->addChild(planeNode().get());
    const Pixels doubled = view(two.get());
    EXPECT_NE(two->compositionKeys()[0].find("ClipRay=[plane,plane];"), std::string::npos);
    EXPECT_TRUE(identical(single, doubled));

    osg::ref_ptr<VolumeScene> none = new VolumeScene;
    none->addChild(node.get());
    EXPECT_LT(covered(single), covered(view(none.get())) - 50) << "the plane must cut something";
}

TEST_F(Equivalence, ClipBoxContainingTheVolumeEqualsNoClipping)
{
    osg::ref_ptr<VolumeNode> node = lumpy();
    osg::ref_ptr<VolumeScene> plain = new VolumeScene;
    plain->addChild(node.get());
    const Pixels unclipped = view(plain.get());

    osg::ref_ptr<VolumeScene> boxed = new VolumeScene;
    boxed->addChild(node.get());
    osg::ref_ptr<ClipBoxNode> box = new ClipBoxNode;
    box->box.set(-10.5, -8.5, -9.5, 10.5, 8.5, 9.5);  // the volume is 20 x 16 x 18
    boxed->addChild(box.get());
    EXPECT_TRUE(identical(view(boxed.get()), unclipped));
    EXPECT_NE(boxed->compositionKeys()[0].find("ClipPosition=[];"), std::string::npos)
        << "a shape that changes nothing is not compiled";

    // The same box run through its shader (forced into the composition) changes nothing either.
    Composition forced;
    forced.instances["ClipPosition"] = {"box"};
    forced.choice["Jitter"] = "null";
    boxed->forcedComposition = forced;
    box->box.set(-10.5, -8.5, -9.5, 10.5, 8.5, 8.99);  // 0.01 below the top face (z = 9): kept
    const Pixels shaderPath = view(boxed.get());
    int differing = 0;
    for (std::size_t i = 0; i < unclipped.rgba.size(); ++i) differing += !(shaderPath.rgba[i] == unclipped.rgba[i]);
    EXPECT_LT(differing, int(unclipped.rgba.size() / 20)) << "only rays through the top 0.01 change";
}

TEST_F(Equivalence, HashJitterDiffersFromNoJitterOnlyByNoise)
{
    osg::ref_ptr<VolumeNode> node = lumpy();
    node->settings.sampleDistanceFactor = 1.0;
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(node.get());
    const Pixels steady = view(scene.get());
    node->settings.functions["Jitter"] = "hash";
    const Pixels jittered = view(scene.get());
    double meanSigned = 0.0, meanAbs = 0.0;
    for (std::size_t i = 0; i < steady.rgba.size(); ++i) {
        const double d = jittered.rgba[i].r() - steady.rgba[i].r();
        meanSigned += d;
        meanAbs += std::abs(d);
    }
    meanSigned /= double(steady.rgba.size());
    meanAbs /= double(steady.rgba.size());
    EXPECT_GT(meanAbs, 1e-4) << "jitter must change samples";
    EXPECT_LT(std::abs(meanSigned), 0.01) << "but not the mean brightness";
    EXPECT_LT(meanAbs, 0.03);
}

TEST_F(Equivalence, RaySetupsAgreeWithTheCameraOutsideAndInside)
{
    // Outside (the existing view) and inside the box (20 x 16 x 18 world units), perspective.
    const osg::Matrixd outside = osg::Matrixd::lookAt(osg::Vec3d(25, -30, 20), osg::Vec3d(), osg::Vec3d(0, 0, 1));
    const osg::Matrixd inside = osg::Matrixd::lookAt(osg::Vec3d(3, 1, 0), osg::Vec3d(-5, 3, 2), osg::Vec3d(0, 0, 1));
    for (const osg::Matrixd& view : {outside, inside}) {
        std::map<std::string, Pixels> images;
        for (const char* setup : {"box_intersection", "hybrid", "rasterised"}) {
            osg::ref_ptr<VolumeNode> node = lumpy();
            node->settings.functions["RaySetup"] = setup;
            images[setup] = render(node.get(), 48, 40, view, osg::Matrixd::perspective(50, 1.2, 0.5, 200));
        }
        const Pixels& reference = images["box_intersection"];
        EXPECT_GT(covered(reference), 400);
        for (const char* setup : {"hybrid", "rasterised"}) {
            const Pixels& p = images[setup];
            double worst = 0.0;
            for (std::size_t i = 0; i < p.rgba.size(); ++i)
                for (int c = 0; c < 4; ++c) worst = std::max(worst, double(std::abs(p.rgba[i][c] - reference.rgba[i][c])));
            EXPECT_LT(worst, 2e-3) << setup << (&view == &inside ? " inside" : " outside");
            EXPECT_EQ(covered(p), covered(reference)) << setup;
        }
    }
}

}  // namespace
}  // namespace volren::test
