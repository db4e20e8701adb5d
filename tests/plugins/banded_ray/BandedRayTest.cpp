// The plugin Shadowing "banded_ray" is known everywhere an implementation is: its parameter in
// `volren render --help-settings`, its bench rows in `volren bench --list-configs`, the settings
// panel (only while it is chosen), scene files (written, read back, refused out of range) and the
// CPU reference, which measures it against the model it declares.
#include "RenderFixture.h"
#include "TestData.h"

#include <volume_gui/RenderSettingsPanel.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/ReferenceModel.h>
#include <volume_reference/ReferenceRenderer.h>
#include <volume_reference/ReferenceSetup.h>
#include <volume_renderer/SceneSettings.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <gtest/gtest.h>

#include <osg/LightSource>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace volren::test {
namespace {

/// The plugin's folders, set before anything asks the registry (it loads plugins once).
const bool pluginFolders = [] {
    setenv("VOLREN_FUNCTION_PATH", BANDED_RAY_LIBRARY_DIR, 1);
    setenv("VOLREN_SHADER_PATH", BANDED_RAY_SHADER_DIR, 1);
    return true;
}();

/// What `volren ARGS` prints (stdout and stderr), with the plugin's folders in its environment.
std::string volren(const std::string& args)
{
    const std::string command = std::string("'") + VOLREN_BINARY_DIR + "/bin/volren' " + args + " 2>&1";
    std::string out;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[4096];
        while (std::size_t n = std::fread(buffer, 1, sizeof(buffer), pipe)) out.append(buffer, n);
        pclose(pipe);
    }
    return out;
}

TEST(BandedRayPlugin, IsRegisteredFromItsFolder)
{
    ASSERT_TRUE(pluginFolders);
    ASSERT_NE(ShaderFunctionRegistry::instance().find("Shadowing", "banded_ray"), nullptr);
}

TEST(BandedRayPlugin, HelpSettingsListItsParameterAndBenchItsRows)
{
    const std::string help = volren("render --help-settings");
    EXPECT_NE(help.find("bandCount"), std::string::npos) << help;
    EXPECT_NE(help.find("in [1, 256] segments; Shadowing banded_ray"), std::string::npos) << help;
    const std::string configs = volren("bench --list-configs");
    EXPECT_NE(configs.find("shadowing=banded_ray  --set shadowing=banded_ray\n"), std::string::npos) << configs;
    EXPECT_NE(configs.find("shadowing=banded_ray+bandCount=32"), std::string::npos) << configs;
}

TEST(BandedRayPlugin, ThePanelShowsItsParameterWhileItIsChosen)
{
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    RenderSettingsPanel panel(node.get(), {});
    auto shown = [&panel] {
        std::vector<std::string> keys;
        for (const ParameterDecl* p : panel.shownParameters()) keys.push_back(p->key);
        return keys;
    };
    EXPECT_TRUE(shown().empty());
    std::string error;
    ASSERT_TRUE(node->settings.set("shadowing", "banded_ray", error)) << error;
    EXPECT_EQ(shown(), std::vector<std::string>{"bandCount"});
    ASSERT_TRUE(node->settings.set("shadowing", "ray", error)) << error;
    EXPECT_EQ(shown(), (std::vector<std::string>{"shadowStepFactor", "shadowCutoff"}));
}

TEST(BandedRayPlugin, SceneFilesKeepItsParameterAndRefuseItOutOfRange)
{
    registerPluginPath();
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    osg::ref_ptr<VolumeNode> node = makeVolumeNode(constantVolume(VoxelType::UInt8, {4, 4, 4}, 7).get(),
                                                   constantTransferFunction(osg::Vec4(1, 1, 1, 0.5f)).get());
    applyNodeSetting(node->settings, "shadowing", "banded_ray", scene->policy());
    applyNodeSetting(node->settings, "bandCount", "5", scene->policy());
    scene->addChild(node.get());
    const std::string path = tempDirectory() + "/banded.osgt";
    ASSERT_TRUE(osgDB::writeNodeFile(*scene, path, new osgDB::Options("volren_embed_voxels")));
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("bandCount \"5\""), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("shadowing \"banded_ray\""), std::string::npos);
    osg::ref_ptr<osg::Node> back = osgDB::readRefNodeFile(path);
    ASSERT_TRUE(back && back->asGroup() && back->asGroup()->getNumChildren() == 1);
    auto* read = dynamic_cast<VolumeNode*>(back->asGroup()->getChild(0));
    ASSERT_TRUE(read);
    EXPECT_EQ(read->settings.parameter<int>("bandCount"), 5);
    EXPECT_EQ(read->settings, node->settings);
    // Out of its declared range: the read fails, naming the key and the range.
    std::string bad = text.str();
    bad.replace(bad.find("bandCount \"5\""), 13, "bandCount \"0\"");
    std::ofstream(path) << bad;
    osgDB::ReaderWriter::ReadResult result = osgDB::Registry::instance()->readNode(path, nullptr, false);
    EXPECT_FALSE(result.validNode());
    EXPECT_NE(result.message().find("bandCount must be a whole number in [1, 256] segments, got '0'"), std::string::npos)
        << result.message();
}

class BandedRayAgainstReference : public RenderFixture
{
};

TEST_F(BandedRayAgainstReference, MatchesTheExactShadowsItDeclaresWithinItsBound)
{
    osg::ref_ptr<VolumeNode> node = makeVolumeNode(constantVolume(VoxelType::UInt8, {16, 16, 16}, 100).get(),
                                                   constantTransferFunction(osg::Vec4(0.9f, 0.6f, 0.3f, 0.08f)).get());
    node->settings.functions["Shading"] = "lighting";
    node->settings.functions["Illumination"] = "lambert";
    node->settings.functions["Shadowing"] = "banded_ray";
    node->settings.parameters["ambient"] = 0.0;
    node->settings.earlyTerminationThreshold = 1.0;
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(node.get());
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(0.4f, -0.6f, 1.0f, 0.0f));
    light->getLight()->setDiffuse(osg::Vec4(1, 1, 1, 1));
    scene->addChild(light.get());

    ReferenceCamera camera;
    camera.width = camera.height = 24;
    camera.view = osg::Matrixd::lookAt(osg::Vec3d(20, -50, 35), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1));
    camera.projection = osg::Matrixd::perspective(40, 1.0, 10, 200);
    const Pixels gpu = render(scene.get(), camera.width, camera.height, camera.view, camera.projection);
    // Its auxiliary volume, made by the pass from its declaration alone: once, the level's size.
    const std::vector<BuiltVolumeStatistics> built = scene->builtVolumeStatistics();
    ASSERT_EQ(built.size(), 1u);
    EXPECT_EQ(built[0].kind, "band extinction");
    EXPECT_EQ(built[0].dims, osg::Vec3i(16, 16, 16));
    EXPECT_EQ(built[0].channels, 1);
    EXPECT_EQ(built[0].builds, 1u);
    const ReferenceSetup setup = referenceSetup(*scene, camera, {});
    ASSERT_EQ(setup.scene.volumes.size(), 1u);
    EXPECT_EQ(setup.scene.volumes[0].shadows, ReferenceScene::Shadows::Exact) << "its declared model";
    const ReferenceImage truth = renderReference(setup.scene, camera, setup.options);
    ReferenceScene unshadowed = setup.scene;
    unshadowed.volumes[0].shadows = ReferenceScene::Shadows::None;
    const ReferenceImage open = renderReference(unshadowed, camera, setup.options);
    const double bound = ReferenceModelCatalog::instance().find("Shadowing", "banded_ray")->bound;
    double worst = 0.0, shadowing = 0.0;
    int covered = 0;
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            covered += truth.at(x, y, 3) > 0.1;
            for (int c = 0; c < 4; ++c) {
                worst = std::max(worst, std::abs(double(gpu.at(x, y)[c]) - truth.at(x, y, c)));
                shadowing = std::max(shadowing, std::abs(open.at(x, y, c) - truth.at(x, y, c)));
            }
        }
    EXPECT_GT(covered, 50);
    EXPECT_GT(shadowing, 0.05) << "shadows change this picture";
    EXPECT_LT(worst, bound);
}

}  // namespace
}  // namespace volren::test
