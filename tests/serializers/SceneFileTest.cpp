// Scene files: every volren class through .osgt, .osgb and .osgx (osgdb_serializers_volren),
// volumes by path relative to the scene file or embedded, sharing kept, bad files rejected
// with messages, and the stock osgconv converting volren scenes.
#include "TestData.h"

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipMaskNode.h>
#include <volume_model/ClipPlaneNode.h>
#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/VolumeNode.h>
#include <volume_renderer/VolumeScene.h>

#include <osg/MatrixTransform>
#include <osg/Notify>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/wait.h>

namespace volren::test {
namespace {

namespace fs = std::filesystem;

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

void writeText(const std::string& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

osg::ref_ptr<osgDB::Options> optionsWith(const std::string& optionString)
{
    return optionString.empty() ? nullptr : new osgDB::Options(optionString);
}

/// Writes `node` to `path`; a test failure with OSG's message when that fails.
void writeScene(const osg::Node& node, const std::string& path, const std::string& optionString = {})
{
    registerPluginPath();
    const osgDB::ReaderWriter::WriteResult result =
        osgDB::Registry::instance()->writeNode(node, path, optionsWith(optionString).get());
    ASSERT_TRUE(result.success()) << path << ": " << result.message();
}

osgDB::ReaderWriter::ReadResult readScene(const std::string& path)
{
    registerPluginPath();
    return osgDB::Registry::instance()->readNode(path, nullptr, false);
}

osg::ref_ptr<osg::Node> readSceneOrFail(const std::string& path)
{
    osgDB::ReaderWriter::ReadResult result = readScene(path);
    EXPECT_TRUE(result.validNode()) << path << ": " << result.message();
    return result.getNode();
}

/// Collects OSG warnings while alive (and passes them on).
class WarningCapture
{
public:
    WarningCapture() : _handler(new Handler(osg::getNotifyHandler())) { osg::setNotifyHandler(_handler.get()); }
    ~WarningCapture() { osg::setNotifyHandler(_handler->previous.get()); }
    std::string text() const { return _handler->text; }

private:
    struct Handler : osg::NotifyHandler
    {
        explicit Handler(osg::NotifyHandler* p) : previous(p) {}
        void notify(osg::NotifySeverity severity, const char* message) override
        {
            if (severity <= osg::WARN) text += message;
            if (previous) previous->notify(severity, message);
        }
        osg::ref_ptr<osg::NotifyHandler> previous;
        std::string text;
    };
    osg::ref_ptr<Handler> _handler;
};

/// The message of a scene read that must fail, followed by the warnings logged meanwhile
/// (OSG may replace the first error by a vaguer one of its own; the warning keeps it).
std::string expectSceneReadError(const std::string& path)
{
    WarningCapture warnings;
    osgDB::ReaderWriter::ReadResult result = readScene(path);
    EXPECT_FALSE(result.validNode()) << path << " was expected to be rejected";
    return result.message() + "\n" + warnings.text();
}

/// A volume whose voxels all differ, in `type`, with channels and frames.
osg::ref_ptr<Volume> patternVolume(VoxelType type, const osg::Vec3i& dims, int channels = 1, int frames = 1)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(type, dims, channels, frames);
    for (std::size_t i = 0; i < v->byteSize(); ++i) v->data()[i] = std::uint8_t((i * 7919u + 13u) >> 3);
    if (type == VoxelType::Float32)  // keep floats finite: clear the exponent's top bit
        for (std::size_t i = 3; i < v->byteSize(); i += 4) v->data()[i] &= 0x3f;
    v->setSpacing({0.5, 0.75, 1.0 / 3.0});
    v->setRescale(0.1, -1024.25);
    v->dirty();
    return v;
}

osg::ref_ptr<TransferFunction> rampTransferFunction()
{
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(0, 0, 0, 0));
    tf->setPoint(1.0 / 7.0, osg::Vec4(0.1f, 0.2f, 1.0f / 3.0f, 0.05f));
    tf->setPoint(200.5, osg::Vec4(1, 0.9f, 0.8f, 0.7f));
    return tf;
}

/// Writes a NRRD volume file at `path` and returns the volume as read back from it.
osg::ref_ptr<Volume> writeVolumeFile(const std::string& path)
{
    registerPluginPath();
    fs::create_directories(fs::path(path).parent_path());
    osg::ref_ptr<Volume> v = patternVolume(VoxelType::Int16, {6, 5, 4});
    EXPECT_TRUE(osgDB::writeObjectFile(*v, path));
    return readVolumeFile(path);
}

/// The scene of the round-trip tests: every volren class, shared objects, non-default fields.
struct TestScene
{
    osg::ref_ptr<VolumeScene> root;
    osg::ref_ptr<Volume> fileVolume;    ///< read from dir/data/head.nrrd, shared by two nodes
    osg::ref_ptr<Volume> memoryVolume;  ///< built in memory, also the clip mask
};

TestScene makeScene(const std::string& dir)
{
    TestScene s;
    s.fileVolume = writeVolumeFile(dir + "/data/head.nrrd");
    s.memoryVolume = patternVolume(VoxelType::UInt16, {3, 4, 5}, 2, 3);
    s.memoryVolume->setName("in memory");

    s.root = new VolumeScene;
    std::string error;
    EXPECT_TRUE(s.root->pass.set("lighting", "off", error)) << error;
    EXPECT_TRUE(s.root->pass.set("forceNullAll", "Jitter,Shadowing", error)) << error;
    EXPECT_TRUE(s.root->pass.set("countSamples", "on", error)) << error;
    s.root->setName("root");

    osg::ref_ptr<TransferFunction> sharedTf = rampTransferFunction();
    osg::ref_ptr<VolumeNode> a = new VolumeNode;
    a->setName("a");
    a->setVolume(s.fileVolume.get());
    a->setTransferFunction(sharedTf.get());
    osg::ref_ptr<VolumeNode> b = new VolumeNode;
    b->setName("b");
    b->setNodeMask(0x5);
    b->setVolume(s.fileVolume.get());
    b->setTransferFunction(sharedTf.get());
    for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
             {"sampleFactor", "0.123456789012345"}, {"isoValue", "-17.125"}, {"ambient", "0.3"},
             {"debugView", "gradient"}, {"traversal", "mip"}, {"gradient", "central9"}, {"forceNull", "Jitter"}})
        EXPECT_TRUE(b->settings.set(key, value, error)) << error;
    b->settings.functions["Jitter"] = "hash";  // chosen and forced to null at once

    osg::ref_ptr<TransferFunction> windowed = rampTransferFunction();
    windowed->setDomain(-0.1, 250.75);
    windowed->setResolution(333);
    windowed->setInterpolation(TransferFunction::Interpolation::MonotoneCubic);
    osg::ref_ptr<VolumeNode> c = new VolumeNode;
    c->setName("c");
    c->setVolume(s.memoryVolume.get());
    c->setTransferFunction(windowed.get());
    // Its two channels: the first through a TF of its own, the second hidden, through the node's.
    c->channels = {{true, colourWindowTransferFunction({0, 1, 0}, 2.5, 40.0, 0.25), 2.5}, {false, nullptr}};
    c->setTimePoint(2);  // the last of its three

    osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(osg::Matrix::translate(1, 2, 3));
    placed->addChild(c.get());

    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(0.6, 0.0, 0.8, -1.0 / 3.0);
    plane->invert = true;
    osg::ref_ptr<ClipBoxNode> box = new ClipBoxNode;
    box->box.set(-1.5, -2, -3, 4, 5, 6.25);
    osg::ref_ptr<ClipEllipsoidNode> ellipsoid = new ClipEllipsoidNode;
    ellipsoid->center.set(0.1, 0.2, 0.3);
    ellipsoid->radii.set(1, 2, 3.5);
    ellipsoid->invert = true;
    osg::ref_ptr<ClipMaskNode> mask = new ClipMaskNode;
    mask->mask = s.memoryVolume;
    mask->threshold = 0.2;

    for (osg::Node* n : std::initializer_list<osg::Node*>{a.get(), b.get(), placed.get(), plane.get(), box.get(),
                                                           ellipsoid.get(), mask.get()})
        s.root->addChild(n);
    return s;
}

void expectSameFile(const std::string& a, const std::string& b)
{
    EXPECT_EQ(fs::weakly_canonical(a), fs::weakly_canonical(b)) << a << " vs " << b;
}

void expectSameVolume(const Volume& a, const Volume& b)
{
    EXPECT_EQ(a.getName(), b.getName());
    EXPECT_EQ(a.type(), b.type());
    EXPECT_EQ(a.dims(), b.dims());
    EXPECT_EQ(a.channels(), b.channels());
    EXPECT_EQ(a.frames(), b.frames());
    EXPECT_EQ(a.spacing(), b.spacing());
    EXPECT_EQ(a.rescaleSlope(), b.rescaleSlope());
    EXPECT_EQ(a.rescaleIntercept(), b.rescaleIntercept());
    ASSERT_EQ(a.byteSize(), b.byteSize());
    EXPECT_EQ(0, std::memcmp(a.block(0, 0), b.block(0, 0), a.byteSize())) << "voxels differ";
}

void expectSameTransferFunction(const TransferFunction& a, const TransferFunction& b)
{
    EXPECT_EQ(a.points(), b.points());
    EXPECT_EQ(a.hasExplicitDomain(), b.hasExplicitDomain());
    EXPECT_EQ(a.domainMin(), b.domainMin());
    EXPECT_EQ(a.domainMax(), b.domainMax());
    EXPECT_EQ(a.resolution(), b.resolution());
    EXPECT_EQ(a.interpolation(), b.interpolation());
}

/// Same classes, node fields and volren fields all the way down (volume files compared as files).
void expectSameNode(const osg::Node& a, const osg::Node& b)
{
    ASSERT_STREQ(a.className(), b.className()) << a.getName();
    EXPECT_EQ(a.getName(), b.getName());
    EXPECT_EQ(a.getNodeMask(), b.getNodeMask()) << a.getName();
    if (auto* va = dynamic_cast<const VolumeNode*>(&a)) {
        auto* vb = dynamic_cast<const VolumeNode*>(&b);
        ASSERT_TRUE(va->getVolume() && vb->getVolume());
        expectSameVolume(*va->getVolume(), *vb->getVolume());
        if (!va->getVolume()->sourceFile.empty()) expectSameFile(va->getVolume()->sourceFile, vb->getVolume()->sourceFile);
        ASSERT_TRUE(va->getTransferFunction() && vb->getTransferFunction());
        expectSameTransferFunction(*va->getTransferFunction(), *vb->getTransferFunction());
        EXPECT_TRUE(va->settings == vb->settings) << a.getName();
        EXPECT_EQ(va->settings.functions, vb->settings.functions);
        EXPECT_EQ(va->timePoint(), vb->timePoint()) << a.getName();
        ASSERT_EQ(va->channels.size(), vb->channels.size()) << a.getName();
        for (std::size_t c = 0; c < va->channels.size(); ++c) {
            EXPECT_EQ(va->channels[c].visible, vb->channels[c].visible) << a.getName() << " channel " << c;
            EXPECT_EQ(va->channels[c].opacity, vb->channels[c].opacity) << a.getName() << " channel " << c;
            const TransferFunction* ta = va->channels[c].transferFunction ? va->channels[c].transferFunction.get()
                                                                          : va->getTransferFunction();
            ASSERT_TRUE(vb->channels[c].transferFunction) << "written as the node's where it names none";
            expectSameTransferFunction(*ta, *vb->channels[c].transferFunction);
        }
    }
    if (auto* pa = dynamic_cast<const ClipPlaneNode*>(&a)) {
        EXPECT_EQ(pa->plane, dynamic_cast<const ClipPlaneNode&>(b).plane);
    }
    if (auto* ba = dynamic_cast<const ClipBoxNode*>(&a)) {
        EXPECT_EQ(ba->box._min, dynamic_cast<const ClipBoxNode&>(b).box._min);
        EXPECT_EQ(ba->box._max, dynamic_cast<const ClipBoxNode&>(b).box._max);
    }
    if (auto* ea = dynamic_cast<const ClipEllipsoidNode*>(&a)) {
        EXPECT_EQ(ea->center, dynamic_cast<const ClipEllipsoidNode&>(b).center);
        EXPECT_EQ(ea->radii, dynamic_cast<const ClipEllipsoidNode&>(b).radii);
    }
    if (auto* ma = dynamic_cast<const ClipMaskNode*>(&a)) {
        auto& mb = dynamic_cast<const ClipMaskNode&>(b);
        EXPECT_EQ(ma->threshold, mb.threshold);
        ASSERT_TRUE(ma->mask && mb.mask);
        expectSameVolume(*ma->mask, *mb.mask);
    }
    if (auto* ca = dynamic_cast<const ClipNode*>(&a)) {
        EXPECT_EQ(ca->invert, dynamic_cast<const ClipNode&>(b).invert);
    }
    if (auto* sa = dynamic_cast<const VolumeScene*>(&a)) {
        auto& sb = dynamic_cast<const VolumeScene&>(b);
        for (const auto& entry : PassSettings::keys())
            EXPECT_EQ(sa->pass.get(entry.first), sb.pass.get(entry.first)) << "pass setting " << entry.first;
    }
    if (auto* ta = dynamic_cast<const osg::MatrixTransform*>(&a)) {
        EXPECT_EQ(ta->getMatrix(), dynamic_cast<const osg::MatrixTransform&>(b).getMatrix());
    }
    if (auto* ga = a.asGroup()) {
        const osg::Group* gb = b.asGroup();
        ASSERT_EQ(ga->getNumChildren(), gb->getNumChildren()) << a.getName();
        for (unsigned i = 0; i < ga->getNumChildren(); ++i) expectSameNode(*ga->getChild(i), *gb->getChild(i));
    }
}

/// Checks what the round-trip scene must keep shared: one Volume for a, b and the mask's
/// source, one TF for a and b, and the in-memory volume shared by c and the clip mask.
void expectSharing(osg::Node* node)
{
    auto* root = dynamic_cast<VolumeScene*>(node);
    ASSERT_TRUE(root);
    ASSERT_EQ(root->getNumChildren(), 7u);
    auto* a = dynamic_cast<VolumeNode*>(root->getChild(0));
    auto* b = dynamic_cast<VolumeNode*>(root->getChild(1));
    auto* c = dynamic_cast<VolumeNode*>(root->getChild(2)->asGroup()->getChild(0));
    auto* mask = dynamic_cast<ClipMaskNode*>(root->getChild(6));
    ASSERT_TRUE(a && b && c && mask);
    EXPECT_EQ(a->getVolume(), b->getVolume());
    EXPECT_EQ(a->getTransferFunction(), b->getTransferFunction());
    EXPECT_NE(a->getTransferFunction(), c->getTransferFunction());
    EXPECT_EQ(c->getVolume(), mask->mask.get());
}

class SceneFileFormats : public ::testing::TestWithParam<std::string>
{
};

TEST_P(SceneFileFormats, EveryClassRoundTripsWithAllFieldsEqual)
{
    const std::string dir = tempDirectory();
    TestScene scene = makeScene(dir);
    const std::string path = dir + "/scene." + GetParam();
    writeScene(*scene.root, path);
    osg::ref_ptr<osg::Node> back = readSceneOrFail(path);
    ASSERT_TRUE(back);
    expectSameNode(*scene.root, *back);
    expectSharing(back.get());
}

TEST_P(SceneFileFormats, SceneMovedWithItsVolumeStillLoads)
{
    const std::string dir = tempDirectory();
    const std::string from = dir + "/first", to = dir + "/elsewhere/second";
    TestScene scene = makeScene(from);
    writeScene(*scene.root, from + "/scene." + GetParam());
    fs::create_directories(fs::path(to).parent_path());
    fs::rename(from, to);
    osg::ref_ptr<osg::Node> back = readSceneOrFail(to + "/scene." + GetParam());
    ASSERT_TRUE(back);
    auto* a = dynamic_cast<VolumeNode*>(back->asGroup()->getChild(0));
    ASSERT_TRUE(a && a->getVolume());
    expectSameFile(a->getVolume()->sourceFile, to + "/data/head.nrrd");
    expectSameVolume(*scene.fileVolume, *a->getVolume());
}

TEST_P(SceneFileFormats, EmbeddedVoxelsRoundTripByteIdentical)
{
    const std::string dir = tempDirectory();
    osg::ref_ptr<VolumeScene> root = new VolumeScene;
    std::vector<osg::ref_ptr<Volume>> volumes;
    for (VoxelType type : {VoxelType::UInt8, VoxelType::Int8, VoxelType::UInt16, VoxelType::Int16, VoxelType::Float32}) {
        volumes.push_back(patternVolume(type, {7, 3, 5}, type == VoxelType::UInt8 ? 3 : 1, type == VoxelType::Int16 ? 2 : 1));
        osg::ref_ptr<VolumeNode> node = new VolumeNode;
        node->setVolume(volumes.back().get());
        root->addChild(node.get());
    }
    // A file-backed volume is embedded on request, and then reads back without its file.
    volumes.push_back(writeVolumeFile(dir + "/data/head.nrrd"));
    osg::ref_ptr<VolumeNode> fromFile = new VolumeNode;
    fromFile->setVolume(volumes.back().get());
    root->addChild(fromFile.get());

    const std::string path = dir + "/embedded." + GetParam();
    writeScene(*root, path, "volren_embed_voxels");
    fs::remove(dir + "/data/head.nrrd");
    osg::ref_ptr<osg::Node> back = readSceneOrFail(path);
    ASSERT_TRUE(back && back->asGroup());
    ASSERT_EQ(back->asGroup()->getNumChildren(), volumes.size());
    for (unsigned i = 0; i < volumes.size(); ++i) {
        auto* node = dynamic_cast<VolumeNode*>(back->asGroup()->getChild(i));
        ASSERT_TRUE(node && node->getVolume());
        expectSameVolume(*volumes[i], *node->getVolume());
    }
}

INSTANTIATE_TEST_SUITE_P(SceneFile, SceneFileFormats, ::testing::Values("osgt", "osgb", "osgx"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(SceneFile, VolumePathIsWrittenRelativeToTheSceneFile)
{
    const std::string dir = tempDirectory();
    TestScene scene = makeScene(dir);
    writeScene(*scene.root, dir + "/scene.osgt");
    const std::string text = readText(dir + "/scene.osgt");
    EXPECT_NE(text.find("SourceFile \"data/head.nrrd\""), std::string::npos) << text;
    // (The NRRD reader names the Volume object after its absolute path; that Name is only a label.)
    EXPECT_EQ(text.find("SourceFile \"" + dir), std::string::npos) << "absolute path written:\n" << text;
    // The shared volume is written once, then referenced by its unique id.
    std::size_t count = 0;
    for (std::size_t at = text.find("SourceFile"); at != std::string::npos; at = text.find("SourceFile", at + 1)) ++count;
    EXPECT_EQ(count, 1u);

    // A scene in a sub-folder refers up and across.
    fs::create_directories(dir + "/scenes/deep");
    writeScene(*scene.root, dir + "/scenes/deep/scene.osgt");
    EXPECT_NE(readText(dir + "/scenes/deep/scene.osgt").find("SourceFile \"../../data/head.nrrd\""), std::string::npos);
    osg::ref_ptr<osg::Node> back = readSceneOrFail(dir + "/scenes/deep/scene.osgt");
    ASSERT_TRUE(back);
    expectSameNode(*scene.root, *back);
}

TEST(SceneFile, NumbersInTextFilesAreExactWhateverThePrecisionOption)
{
    const std::string dir = tempDirectory();
    TestScene scene = makeScene(dir);
    writeScene(*scene.root, dir + "/scene.osgt", "PRECISION 3");
    osg::ref_ptr<osg::Node> back = readSceneOrFail(dir + "/scene.osgt");
    ASSERT_TRUE(back);
    // OSG's own matrix loses digits under PRECISION 3; the volren fields must not.
    auto* b = dynamic_cast<VolumeNode*>(back->asGroup()->getChild(1));
    ASSERT_TRUE(b);
    EXPECT_EQ(b->settings.sampleDistanceFactor, 0.123456789012345);
    auto* plane = dynamic_cast<ClipPlaneNode*>(back->asGroup()->getChild(3));
    ASSERT_TRUE(plane);
    EXPECT_EQ(plane->plane[3], -1.0 / 3.0);
}

TEST(SceneFile, SettingsSerializerCoversEveryRenderSettingsKey)
{
    // Guards against drift: each key RenderSettings::keys() lists gets a non-default value
    // (high-precision numbers first, so a setting written with rounding fails here) and must
    // survive the round trip.
    const std::string dir = tempDirectory();
    const std::vector<std::string> candidates = {"0.123456789012345", "0.987654321098765", "3.14159265358979",
                                                 "null", "7", "scalar", "Gradient", "on", "off", "16bit",
                                                 "0:0.123456789012345,0.987654321098765:1"};
    for (const auto& [key, what] : RenderSettings::keys()) {
        osg::ref_ptr<VolumeNode> node = new VolumeNode;
        std::string error;
        bool changed = false;
        for (const std::string& value : candidates) {
            RenderSettings probe;
            if (probe.set(key, value, error) && probe != RenderSettings()) {
                node->settings = probe;
                changed = true;
                break;
            }
        }
        EXPECT_TRUE(changed) << "no test value for setting '" << key << "' (" << what << ")";
        for (const char* ext : {"osgt", "osgb"}) {
            const std::string path = dir + "/settings." + ext;
            writeScene(*node, path);
            osg::ref_ptr<VolumeNode> back = dynamic_cast<VolumeNode*>(readSceneOrFail(path).get());
            ASSERT_TRUE(back) << key;
            EXPECT_TRUE(back->settings == node->settings) << "setting '" << key << "' lost through ." << ext;
        }
    }
}

// --- Bad scene files ---------------------------------------------------------------------

class SceneFileBad : public ::testing::Test
{
protected:
    void SetUp() override
    {
        dir = tempDirectory();
        scene = makeScene(dir);
        writeScene(*scene.root, dir + "/scene.osgt");
        writeScene(*scene.root, dir + "/scene.osgb");
        text = readText(dir + "/scene.osgt");
    }
    /// The scene text with the first `from` replaced by `to`, written as bad.osgt.
    std::string edited(const std::string& from, const std::string& to)
    {
        std::string t = text;
        const std::size_t at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) t.replace(at, from.size(), to);
        writeText(dir + "/bad.osgt", t);
        return dir + "/bad.osgt";
    }
    std::string dir, text;
    TestScene scene;
};

TEST_F(SceneFileBad, ATextSceneWrittenBeforeChannelOpacitiesReadsThemAsOne)
{
    // Scenes from before the channels' Opacity field (the first Channels files) still read.
    const std::string older = std::regex_replace(text, std::regex("Opacity [^ \n]+ ?"), "");
    ASSERT_EQ(older.find("Opacity"), std::string::npos);
    writeText(dir + "/older.osgt", older);
    osg::ref_ptr<osg::Node> root = readSceneOrFail(dir + "/older.osgt");
    ASSERT_TRUE(root);
    std::vector<VolumeNode*> nodes = findVolumeNodes(*root);
    bool found = false;
    for (VolumeNode* node : nodes)
        for (const ChannelDisplay& channel : node->channels) {
            found = true;
            EXPECT_EQ(channel.opacity, 1.0);
        }
    EXPECT_TRUE(found) << "the scene has channel displays";
}

TEST_F(SceneFileBad, MissingVolumeFileFailsNamingIt)
{
    fs::remove(dir + "/data/head.nrrd");
    for (const char* ext : {"osgt", "osgb"}) {
        const std::string message = expectSceneReadError(dir + "/scene." + ext);
        EXPECT_NE(message.find("data/head.nrrd"), std::string::npos) << message;
        EXPECT_NE(message.find("not found"), std::string::npos) << message;
    }
}

TEST_F(SceneFileBad, VolumeWithNeitherFileNorVoxelsFails)
{
    const std::string message = expectSceneReadError(edited("SourceFile \"data/head.nrrd\"", ""));
    EXPECT_NE(message.find("no SourceFile and no Voxels"), std::string::npos) << message;
}

TEST_F(SceneFileBad, UnreadableVolumeFileFailsWithTheReadersReason)
{
    writeText(dir + "/data/head.nrrd", "NRRD0004\ntype: banana\n\n");
    for (const char* ext : {"osgt", "osgb"}) {
        const std::string message = expectSceneReadError(dir + "/scene." + ext);
        EXPECT_NE(message.find("head.nrrd"), std::string::npos) << message;
        EXPECT_NE(message.find("volren::Volume SourceFile"), std::string::npos) << message;
    }
}

TEST_F(SceneFileBad, WrongValueTypesFailNamingTheField)
{
    const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
        {"Spacing ", "Spacing banana ", "volren::Volume Spacing: expected a number, got 'banana'"},
        {"Invert TRUE", "Invert maybe", "volren::ClipNode Invert: expected TRUE or FALSE, got 'maybe'"},
        {"Threshold 0.2", "Threshold 1e999", "volren::ClipMaskNode Threshold: expected a number"},
        {"\"mip\"", "\"m-i-p\"", "slot RayTraversal has no implementation 'm-i-p'"},
        {"ambient \"0.3\"", "ambient \"3\"", "ambient must be a number in [0, 1]"},
        {"ambient \"0.3\"", "brightness \"3\"", "unknown setting 'brightness'"},
        {"lighting \"off\"", "lighting \"dim\"", "lighting must be on or off"},
        {"Radii 1 2 3.5", "Radii 1 -2 3.5", "semi-axes must be positive"},
        {"Resolution 333", "Resolution 1", "resolution must be 2..65536"},
        {"Type uint16", "Type uint12", "unknown voxel type 'uint12'"},
        {"Dims 3 4 5", "Dims 3 4 5.5", "Dims: expected an integer, got '5.5'"},
        {"Visible TRUE", "Visible maybe", "volren::VolumeNode Channels 0 Visible: expected TRUE or FALSE, got 'maybe'"},
        {"Channels 2 {", "Channels -2 {", "volren::VolumeNode Channels: -2 is not in [0, 4096]"},
        {"Opacity 2.5", "Opacity -2.5", "volren::VolumeNode Channels 0 Opacity: -2.5"},
        {"Opacity 2.5", "Opacity lots", "volren::VolumeNode Channels 0 Opacity: expected a number, got 'lots'"},
        {"TimePoint 2", "TimePoint -1", "volren::VolumeNode TimePoint: -1 is not in [0, 1000000000]"},
    };
    for (const auto& [from, to, expected] : cases) {
        const std::string message = expectSceneReadError(edited(from, to));
        EXPECT_NE(message.find(expected), std::string::npos) << to << " gave: " << message;
    }
}

TEST_F(SceneFileBad, NestedObjectOfTheWrongClassFails)
{
    // A transfer function where the volume belongs.
    const std::string message = expectSceneReadError(edited("volren::Volume {", "volren::TransferFunction {"));
    EXPECT_NE(message.find("volren::VolumeNode Volume is a volren::TransferFunction, not a volren::Volume"),
              std::string::npos)
        << message;
}

TEST_F(SceneFileBad, TruncatedAndGarbageFilesFailWithoutCrashing)
{
    // Text files are cut at line ends: OSG 3.6.5's own reader of quoted strings (object names)
    // loops forever on a file that ends inside one; volren's fields do not use it.
    for (std::size_t cut : {std::size_t(20), text.size() / 3, text.size() / 2, text.size() - 10}) {
        const std::size_t keep = text.find('\n', cut);
        writeText(dir + "/bad.osgt", text.substr(0, keep));
        osgDB::ReaderWriter::ReadResult result = readScene(dir + "/bad.osgt");
        // OSG may return the part read so far for a cut text file; it must not crash, and a
        // file cut inside a volren value must fail.
        if (result.validNode()) {
            EXPECT_TRUE(result.getNode()->asGroup()) << keep;
        }
    }
    const std::string binary = readText(dir + "/scene.osgb");
    for (std::size_t keep : {std::size_t(20), binary.size() / 2, binary.size() - 10}) {
        writeText(dir + "/bad.osgb", binary.substr(0, keep));
        osgDB::ReaderWriter::ReadResult result = readScene(dir + "/bad.osgb");
        EXPECT_FALSE(result.validNode() && result.getNode()->asGroup() &&
                     result.getNode()->asGroup()->getNumChildren() == 7u)
            << "a cut binary file read as whole";
    }
    writeText(dir + "/bad.osgt", "#Ascii Scene\n#Version 161\n{ { } } }} volren::VolumeNode");
    EXPECT_FALSE(readScene(dir + "/bad.osgt").validNode());
    writeText(dir + "/bad.osgt", "this is not a scene file at all");
    EXPECT_FALSE(readScene(dir + "/bad.osgt").validNode());
}

TEST_F(SceneFileBad, UnknownClassIsRejectedOrWarnedAbout)
{
    // As the root: the read fails.
    writeText(dir + "/bad.osgt", "#Ascii Scene\n#Version 161\n#Generator OpenSceneGraph 3.6.5\n\n"
                                 "volren::NoSuchNode {\n  UniqueID 1\n}\n");
    EXPECT_FALSE(readScene(dir + "/bad.osgt").validNode());
    // Inside a group: OSG warns, naming the class, and skips it.
    WarningCapture warnings;
    readScene(edited("volren::ClipBoxNode {", "volren::ClipCylinderNode {"));
    EXPECT_NE(warnings.text().find("volren::ClipCylinderNode"), std::string::npos) << warnings.text();
}

/// The volren program's exit code and output for `arguments` (skipped when it is not built).
std::pair<int, std::string> runVolren(const std::string& arguments, const std::string& dir)
{
    const std::string program = std::string(VOLREN_BINARY_DIR) + "/bin/volren";
    if (!fs::exists(program)) return {-1, "volren is not built"};
    const std::string log = dir + "/volren.log";
    const int status = std::system((program + " " + arguments + " > " + log + " 2>&1").c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readText(log)};
}

TEST_F(SceneFileBad, VolrenRenderExitsOneNamingTheSceneFile)
{
    if (!fs::exists(std::string(VOLREN_BINARY_DIR) + "/bin/volren")) GTEST_SKIP() << "volren is not built";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"Spacing ", "Spacing banana "},
        {"volren::ClipBoxNode {", "volren::ClipCylinderNode {"},
        {"SourceFile \"data/head.nrrd\"", "SourceFile \"data/nothere.nrrd\""},
    };
    for (const auto& [from, to] : cases) {
        const std::string bad = edited(from, to);
        const auto [code, output] = runVolren("render " + bad + " -o " + dir + "/out.png --size 8x8", dir);
        EXPECT_EQ(code, 1) << to << ": " << output;
        EXPECT_NE(output.find(bad), std::string::npos) << output;
    }
    writeText(dir + "/bad.osgt", "this is not a scene file at all");
    const auto [code, output] = runVolren("render " + dir + "/bad.osgt -o " + dir + "/out.png --size 8x8", dir);
    EXPECT_EQ(code, 1) << output;
    EXPECT_NE(output.find(dir + "/bad.osgt"), std::string::npos) << output;
}

// --- Stock OSG tools -------------------------------------------------------------------------

TEST(SceneFile, StockOsgconvConvertsVolrenScenes)
{
    const std::string osgconv = "/usr/bin/osgconv";
    if (!fs::exists(osgconv)) GTEST_SKIP() << osgconv << " is not installed";
    const std::string dir = tempDirectory();
    TestScene scene = makeScene(dir);
    writeScene(*scene.root, dir + "/scene.osgt");
    const std::string env = "OSG_LIBRARY_PATH=" + std::string(VOLREN_BINARY_DIR) + "/lib ";
    for (const std::string step : {"scene.osgt scene.osgb", "scene.osgb back.osgt"}) {
        const std::string command = "cd " + dir + " && " + env + osgconv + " " + step + " > osgconv.log 2>&1";
        EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << readText(dir + "/osgconv.log");
    }
    const std::string back = readText(dir + "/back.osgt");
    EXPECT_NE(back.find("volren::VolumeNode"), std::string::npos) << back.substr(0, 2000);
    EXPECT_NE(back.find("SourceFile \"data/head.nrrd\""), std::string::npos);
    osg::ref_ptr<osg::Node> node = readSceneOrFail(dir + "/back.osgt");
    ASSERT_TRUE(node);
    expectSameNode(*scene.root, *node);
    expectSharing(node.get());
}

}  // namespace
}  // namespace volren::test
