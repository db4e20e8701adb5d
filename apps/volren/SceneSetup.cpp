#include "SceneSetup.h"
#include "Commands.h"
#include "DefaultSceneText.h"

#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/TransferFunctionFile.h>
#include <volume_model/VolumeNode.h>

#include <osg/NodeVisitor>
#include <osg/Notify>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>

#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/Slots.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

namespace volren::app {

std::vector<VolumeNode*> volumeNodes(osg::Node& root)
{
    struct Collect : osg::NodeVisitor
    {
        Collect() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        std::vector<VolumeNode*> nodes;
        void apply(osg::Node& node) override
        {
            if (auto* v = dynamic_cast<VolumeNode*>(&node)) nodes.push_back(v);
            traverse(node);
        }
    } collect;
    root.accept(collect);
    return collect.nodes;
}

namespace {

/// Collects what OSG's scene-file parser and the volren serializers warn about while a scene is
/// read (OSG skips unknown classes and properties; after a volren field fails, OSG may replace
/// that error by a vaguer one), passing every message on to the usual handler.
class ParserWarnings : public osg::NotifyHandler
{
public:
    ParserWarnings() : _previous(osg::getNotifyHandler()) {}
    void notify(osg::NotifySeverity severity, const char* message) override
    {
        const std::string text = message;
        if (severity <= osg::WARN && collected.empty() &&
            (text.rfind("volren::", 0) == 0 || text.rfind("InputStream", 0) == 0 ||
             text.rfind("AsciiInputIterator", 0) == 0 || text.rfind("XmlInputIterator", 0) == 0 ||
             text.rfind("ObjectWrapper", 0) == 0))
            collected = text.substr(0, text.find_last_not_of("\r\n") + 1);
        if (_previous) _previous->notify(severity, message);
    }
    osg::NotifyHandler* previous() const { return _previous.get(); }
    std::string collected;  ///< the first warning: the cause (later ones are its consequences)

private:
    osg::ref_ptr<osg::NotifyHandler> _previous;
};

}  // namespace

std::string inputName(const RenderOptions& options)
{
    return options.input.empty() ? std::string("the default scene (scenes/default.osgt)") : options.input;
}

namespace {

/// Reads a scene with `read`, turning what OSG's parser only warns about into an error.
osg::ref_ptr<osg::Node> readScene(const std::function<osgDB::ReaderWriter::ReadResult()>& read, const std::string& name)
{
    osg::ref_ptr<ParserWarnings> warnings = new ParserWarnings;
    osg::setNotifyHandler(warnings.get());
    osgDB::ReaderWriter::ReadResult result = read();
    osg::setNotifyHandler(warnings->previous());
    if (!result.validNode() || !warnings->collected.empty()) {
        const std::string why = !warnings->collected.empty() ? warnings->collected
                                : !result.message().empty()  ? result.message()
                                                             : "no reader for this file type, or the file is invalid";
        throw std::runtime_error(name + ": cannot read scene: " + why);
    }
    return result.getNode();
}

}  // namespace

osg::ref_ptr<VolumeScene> loadScene(const RenderOptions& options)
{
    registerPluginPath();
    const std::string input = options.input;
    osg::ref_ptr<osg::Node> scene;
    if (input.empty()) {
        // The compiled-in scenes/default.osgt; its relative file names resolve in share/volren/data.
        osg::ref_ptr<osgDB::Options> where = new osgDB::Options;
        where->getDatabasePathList().push_back(osgDB::concatPaths(shareDirectory(), "data"));
        osgDB::ReaderWriter* osgt = osgDB::Registry::instance()->getReaderWriterForExtension("osgt");
        if (!osgt) throw std::runtime_error("OSG's osgt plugin (osgdb_osg) is missing");
        std::istringstream text(defaultSceneText());
        scene = readScene([&] { return osgt->readNode(text, where.get()); }, inputName(options));
    } else if (isVolumeFile(input)) {
        scene = makeDefaultScene(readVolumeWithProgress(input).get());
    } else {
        if (!osgDB::fileExists(input)) throw std::runtime_error(input + ": no such file");
        scene = readScene([&] { return osgDB::Registry::instance()->readNode(input, nullptr); }, input);
    }

    osg::ref_ptr<VolumeScene> root = dynamic_cast<VolumeScene*>(scene.get());
    if (!root) {
        root = new VolumeScene;
        root->addChild(scene.get());
    }
    const std::vector<VolumeNode*> nodes = volumeNodes(*root);
    if (!options.tfFile.empty()) {
        osg::ref_ptr<TransferFunction> tf = readTransferFunctionFile(options.tfFile);
        // ParaView presets are made for any data: like ParaView, map them onto each volume's range.
        const bool preset = isParaViewPreset(options.tfFile) && !options.tfKeepRange;
        for (VolumeNode* node : nodes) {
            if (preset && node->getVolume()) {
                osg::ref_ptr<TransferFunction> fitted = new TransferFunction(*tf);
                const auto [lo, hi] = node->getVolume()->valueRange();
                fitted->remap(lo, hi > lo ? hi : lo + 1.0);
                node->setTransferFunction(fitted.get());
            } else {
                node->setTransferFunction(tf.get());
            }
        }
    }
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    for (const auto& [key, value] : options.settings) {
        std::string error;
        bool passKey = false;
        for (const auto& entry : VolumeScene::keys()) passKey = passKey || entry.first == key;
        if (passKey) {
            if (!root->set(key, value, error)) throw UsageError("--set " + key + "=" + value + ": " + error);
            continue;
        }
        RenderSettings probe;
        if (!probe.set(key, value, error)) throw UsageError("--set " + key + "=" + value + ": " + error);
        if (const std::string slot = RenderSettings::slotForKey(key); !slot.empty()) {
            const std::string name = probe.functions.at(slot);
            if (!registry.find(slot, name)) {
                std::string known;
                for (const auto& n : registry.names(slot)) known += (known.empty() ? "" : ", ") + n;
                throw UsageError("--set " + key + "=" + value + ": slot " + slot + " has no implementation '" + name +
                                 "' (known: " + known + ")");
            }
        }
        for (VolumeNode* node : nodes) node->settings.set(key, value, error);
    }
    return root;
}

std::string settingsHelp()
{
    std::ostringstream out;
    const RenderSettings defaults;
    out << "Per-volume settings (--set KEY=VALUE; value shown is the default, empty = chosen by the scene):\n";
    for (const auto& [key, what] : RenderSettings::keys())
        out << "  " << std::left << std::setw(18) << key << std::setw(14) << defaults.get(key) << what << "\n";
    out << "Pass settings:\n";
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    for (const auto& [key, what] : VolumeScene::keys())
        out << "  " << std::left << std::setw(18) << key << std::setw(14) << scene->get(key) << what << "\n";
    out << "Implementations per slot (default first):\n";
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    for (const SlotInfo& s : slots()) {
        std::string key;
        for (const auto& entry : RenderSettings::keys())
            if (RenderSettings::slotForKey(entry.first) == s.name) key = entry.first;
        out << "  " << std::left << std::setw(16) << s.name << "(" << key << "): " << s.defaultFunction;
        for (const auto& name : registry.names(s.name))
            if (name != s.defaultFunction) out << ", " << name;
        out << (s.isTemplate ? "   [one instance per clip shape, chosen by the scene]" : "") << "\n";
    }
    return out.str();
}

void setUpCamera(osg::Camera& camera, const osg::Node& scene, const RenderOptions& options, double aspect)
{
    const osg::BoundingSphere bound = scene.getBound();
    const osg::Vec3d centre = options.center ? *options.center : osg::Vec3d(bound.center());
    const double radius = bound.valid() && bound.radius() > 0 ? bound.radius() : 1.0;
    const double fov = options.fov ? *options.fov : 30.0;

    osg::Vec3d eye;
    if (options.eye) {
        eye = *options.eye;
    } else {
        osg::Vec3d direction(0.55, 1.0, 0.35);
        direction.normalize();
        const double halfV = osg::DegreesToRadians(fov * 0.5);
        const double halfAngle = std::min(halfV, std::atan(std::tan(halfV) * aspect));
        eye = centre + direction * (radius / std::sin(halfAngle) * 1.02);
    }
    const osg::Vec3d up = options.up ? *options.up : osg::Vec3d(0.0, 0.0, 1.0);
    if ((eye - centre).length() == 0.0) throw UsageError("--eye and --center must differ");
    if (((centre - eye) ^ up).length() == 0.0) throw UsageError("--up must not be parallel to the view direction");
    camera.setViewMatrixAsLookAt(eye, centre, up);

    if (options.orthoHeight) {
        const double h = *options.orthoHeight * 0.5;
        camera.setProjectionMatrixAsOrtho(-h * aspect, h * aspect, -h, h, 0.01, 1e6);
    } else {
        camera.setProjectionMatrixAsPerspective(fov, aspect, 0.01, 1e6);
    }
}

}  // namespace volren::app
