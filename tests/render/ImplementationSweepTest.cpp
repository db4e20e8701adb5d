// Every registered implementation of every slot renders a small lit, clipped volume without
// GL errors, link failures or NaN pixels.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_renderer/Permutations.h>
#include <volume_renderer/Slots.h>

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipMaskNode.h>
#include <volume_model/ClipPlaneNode.h>

#include <osg/LightSource>

#include <cmath>

namespace volren::test {
namespace {

struct Implementation
{
    std::string slot, name;
};

void PrintTo(const Implementation& i, std::ostream* out) { *out << i.slot << "/" << i.name; }

/// The policy's choice with `impl` (and `traversal`, unless empty) asked for.
Composition compositionWith(const Implementation& impl, const std::string& traversal)
{
    const CompositionPolicy policy;
    RenderSettings settings;
    if (!traversal.empty()) settings.functions["RayTraversal"] = traversal;
    if (!findSlot(impl.slot)->isTemplate) settings.functions[impl.slot] = impl.name;
    static osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    SceneOffer offer;
    offer.lights.resize(1);
    offer.clips.push_back({plane.get(), osg::Matrixd()});
    Composition c = policy.choose(settings, offer, {}).composition;
    if (findSlot(impl.slot)->isTemplate) {
        c.instances.clear();
        if (impl.name != "null") c.instances[impl.slot] = {impl.name};
    }
    return c;
}

std::vector<Implementation> allImplementations()
{
    std::vector<Implementation> all;
    for (const SlotInfo& s : slots())
        for (const std::string& name : ShaderFunctionRegistry::instance().names(s.name)) all.push_back({s.name, name});
    return all;
}

/// The policy's choice for a lit, clipped volume (every clip kind offered) with `impl` asked for,
/// or, for a template slot, its instances narrowed to `impl` alone; with the default traversal,
/// else the first with which it is valid (an Acceleration works with the traversals that take
/// its leaps).
Composition compositionWith(const Implementation& impl)
{
    Composition c = compositionWith(impl, "");
    for (const std::string& traversal : ShaderFunctionRegistry::instance().names("RayTraversal")) {
        if (CompositionPolicy().invalidReason(c).empty() || impl.slot == "RayTraversal") break;
        c = compositionWith(impl, traversal);
    }
    return c;
}

class EveryImplementation : public RenderFixture, public ::testing::WithParamInterface<Implementation>
{
};

TEST_P(EveryImplementation, RendersWithoutGlErrorsOrNaN)
{
    const Implementation impl = GetParam();
    const Composition composition = compositionWith(impl);
    ASSERT_EQ(CompositionPolicy().invalidReason(composition), "") << composition.key();

    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::Float32, {12, 10, 8});
    auto* v = reinterpret_cast<float*>(volume->data());
    for (int z = 0; z < 8; ++z)
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 12; ++x) v[x + 12 * (y + 10 * z)] = float(std::sin(x * 0.7) * std::cos(y * 0.5) + z * 0.1);
    volume->dirty();
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(-1.0, osg::Vec4(0, 0, 1, 0));
    tf->setPoint(1.7, osg::Vec4(1, 0.5f, 0, 0.6f));
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(volumeNode(volume.get(), tf.get(), true).get());
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(0.3f, -1, 1, 0));
    scene->addChild(light.get());
    // One shape of every kind, each cutting the volume, so every template instance binds one.
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(1.0, 0.2, 0.0, 3.0);
    scene->addChild(plane.get());
    osg::ref_ptr<ClipBoxNode> box = new ClipBoxNode;
    box->box.set(-5, -4, -3, 5, 4, 3);
    scene->addChild(box.get());
    osg::ref_ptr<ClipEllipsoidNode> ellipsoid = new ClipEllipsoidNode;
    ellipsoid->radii.set(7, 6, 5);
    ellipsoid->invert = true;
    scene->addChild(ellipsoid.get());
    osg::ref_ptr<ClipMaskNode> mask = new ClipMaskNode;
    mask->mask = volume;
    mask->threshold = 0.2;
    scene->addChild(mask.get());
    scene->forcedComposition = composition;

    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(14, -18, 11), osg::Vec3d(), osg::Vec3d(0, 0, 1));
    const Pixels img = render(scene.get(), 24, 20, view, osg::Matrixd::perspective(40, 1.2, 1, 100));
    ASSERT_EQ(scene->compositionKeys().size(), 1u);
    EXPECT_EQ(scene->compositionKeys()[0], composition.key());
    for (const osg::Vec4& p : img.rgba)
        for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(p[c])) << composition.key();
}

INSTANTIATE_TEST_SUITE_P(AllSlots, EveryImplementation, ::testing::ValuesIn(allImplementations()),
                         [](const ::testing::TestParamInfo<Implementation>& info) {
                             return info.param.slot + "_" + info.param.name;
                         });

}  // namespace
}  // namespace volren::test
