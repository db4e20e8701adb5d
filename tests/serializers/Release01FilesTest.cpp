// Scene files written by release 0.1 (tests/serializers/release01: every example scene and one
// setting every key it had, each written by that release's `volren convert`) read into the
// same settings and write back byte for byte: moving implementation parameters out of
// RenderSettings into declarations changed neither what a file means nor how it is written.
#include "TestData.h"

#include <volume_model/ReadVolume.h>
#include <volume_model/RenderSettings.h>
#include <volume_model/SceneInputs.h>
#include <volume_model/SpatialWeighting.h>
#include <volume_model/VolumeNode.h>
#include <volume_renderer/VolumeScene.h>

#include <gtest/gtest.h>

#include <osgDB/ReadFile>
#include <osgDB/Registry>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace volren::test {
namespace {

const std::string folder = std::string(VOLREN_SOURCE_DIR) + "/tests/serializers/release01";

std::string fileText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// `node` as a .osgt file in `folder` would hold it (paths relative to that folder).
std::string written(const osg::Node& node)
{
    osgDB::ReaderWriter* writer = osgDB::Registry::instance()->getReaderWriterForExtension("osgt");
    EXPECT_TRUE(writer);
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setPluginStringData("fileType", "Ascii");
    options->getDatabasePathList().push_back(folder);
    std::ostringstream out;
    const osgDB::ReaderWriter::WriteResult result = writer->writeNode(node, out, options.get());
    EXPECT_TRUE(result.success()) << result.message();
    return out.str();
}

/// `path` read as `volren convert` read it from the repository's root when it wrote the files
/// (strictly; models as ProxyNodes named from there).
osg::ref_ptr<osg::Node> readAsConvertDoes(const std::string& path)
{
    registerPluginPath();
    struct InRoot
    {
        const fs::path before = fs::current_path();
        InRoot() { fs::current_path(VOLREN_SOURCE_DIR); }
        ~InRoot() { fs::current_path(before); }
    } inRoot;
    osg::ref_ptr<osg::Group> scene = readSceneInputs({{path, std::nullopt}}, [](const std::string& file) {
        return readVolumeFile(file);
    });
    makeModelPathsRelative(*scene, folder);
    return scene;
}

/// `text` without what stock osg::ProxyNode writes of a model that the scene names by its data-path
/// name (isosurface-mesh's glider): release 0.1's convert wrote that name relative to its working
/// directory, where it is not found, so no reader writes it back alike (a defect of its own,
/// unrelated to settings). Everything else is compared byte for byte.
std::string withoutUnresolvedModels(const std::string& text)
{
    std::istringstream in(text);
    std::string out, line;
    while (std::getline(in, line)) {
        if (line.find("meshes/glider.osg\" ") != std::string::npos || line == "          Children 0 " || line.empty())
            continue;
        out += line + "\n";
    }
    return out;
}

/// The first volume node below `node`.
VolumeNode* firstVolumeNode(osg::Node* node)
{
    if (auto* v = dynamic_cast<VolumeNode*>(node)) return v;
    if (osg::Group* g = node ? node->asGroup() : nullptr)
        for (unsigned i = 0; i < g->getNumChildren(); ++i)
            if (VolumeNode* v = firstVolumeNode(g->getChild(i))) return v;
    return nullptr;
}

class Release01Files : public ::testing::TestWithParam<std::string>
{
};

TEST_P(Release01Files, ReadAndWriteBackByteForByte)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string path = folder + "/" + GetParam();
    osg::ref_ptr<osg::Node> scene = readAsConvertDoes(path);
    ASSERT_TRUE(scene) << path;
    const std::string before = withoutUnresolvedModels(fileText(path)), after = withoutUnresolvedModels(written(*scene));
    EXPECT_EQ(after, before) << GetParam() << " reads and writes back unchanged";
}

INSTANTIATE_TEST_SUITE_P(Scenes, Release01Files,
                         ::testing::Values("default.osgt", "ct-instrument.osgt", "isosurface-mesh.osgt",
                                           "microscopy-anisotropic.osgt", "mri-clip-plane.osgt", "two-volumes.osgt",
                                           "every-setting.osgt"),
                         [](const auto& info) {
                             std::string name = info.param.substr(0, info.param.find('.'));
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

TEST(Release01Settings, EveryKeyReadsAsReleaseOneWroteIt)
{
    VOLREN_REQUIRE_SHARED_DATA();
    const std::string path = folder + "/every-setting.osgt";
    osg::ref_ptr<osg::Node> scene = readAsConvertDoes(path);
    ASSERT_TRUE(scene) << path;
    VolumeNode* node = firstVolumeNode(scene.get());
    ASSERT_TRUE(node);
    // The pairs as the file holds them, read with a regex of their own.
    const std::string text = fileText(path);
    const std::regex pair("\\n        ([A-Za-z]+) \"([^\"]*)\" ");
    std::map<std::string, std::string> pairs;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), pair); it != std::sregex_iterator(); ++it)
        pairs[(*it)[1]] = (*it)[2];
    ASSERT_EQ(pairs.size(), 47u) << "every key release 0.1 had";
    for (const auto& [key, value] : pairs) {
        if (RenderSettings::slotForKey(key).empty())
            EXPECT_EQ(node->settings.get(key), value) << key;
        else
            EXPECT_EQ(node->settings.functions.at(RenderSettings::slotForKey(key)), value) << key;
    }
    // And what the implementations read: closed values, not the text again.
    EXPECT_EQ(node->settings.number("coneAngle"), 15.0);
    EXPECT_EQ(node->settings.number("isoValue"), 80.5);
    EXPECT_EQ(node->settings.parameter<int>("adaptiveSteps"), 8);
    EXPECT_EQ(node->settings.parameter<std::string>("debugView"), "gradient");
    EXPECT_DOUBLE_EQ(spatialWeighting(node->settings)(0.5, 0.0, 0.5), 0.5) << "weightY 0:0.5,1:1 at y = 0";
    EXPECT_EQ(node->settings.forceNull, std::set<std::string>{"Jitter"});
    EXPECT_EQ(node->settings.sampleDistanceFactor, 0.25);
}

}  // namespace
}  // namespace volren::test
