#include <volume_model/DataSearchPath.h>
#include <volume_model/DefaultScene.h>
#include <volume_model/ParseNumber.h>
#include <volume_model/ReadScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/SceneInputs.h>

#include <osg/LightSource>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/ProxyNode>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace volren {

namespace {

/// The numbers of one comma-separated field of a placement.
std::vector<double> numbers(const std::string& field, const std::string& text)
{
    std::vector<double> values;
    std::stringstream in(field);
    std::string part;
    while (std::getline(in, part, ',')) {
        double v = 0.0;
        if (!parseFiniteNumber(part, v))
            throw std::invalid_argument("'" + text + "': '" + part + "' is not a number");
        values.push_back(v);
    }
    return values;
}

bool isSceneRoot(const osg::Node& node)
{
    return std::string(node.libraryName()) == "volren" && std::string(node.className()) == "VolumeScene";
}

bool hasLight(osg::Node& root)
{
    struct Find : osg::NodeVisitor
    {
        Find() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        bool found = false;
        void apply(osg::LightSource&) override { found = true; }
    } find;
    root.accept(find);
    return find.found;
}

/// The file an input names: as given when it exists (or is a slice pattern), else found along
/// OSG's data file path (as osgviewer finds its files); throws naming every folder searched.
std::string locate(const std::string& path)
{
    if (path.find_first_of("*?") != std::string::npos || osgDB::fileExists(path)) return path;
    const std::string found = findDataFileFrom(path, "");
    if (found.empty())
        throw std::runtime_error(path + ": no such file (looked in " + searchedFolders("") +
                                 "; OSG_FILE_PATH adds folders)");
    return found;
}

/// The nodes one input adds to the combined scene.
std::vector<osg::ref_ptr<osg::Node>> readPart(const SceneInput& given, const VolumeFileReader& readVolume,
                                              osg::ref_ptr<osg::Group>& root)
{
    SceneInput input = given;
    input.path = locate(given.path);
    switch (inputKind(input.path)) {
    case InputKind::Volume: {
        osg::ref_ptr<Volume> volume = readVolume(input.path);
        return {makeDefaultVolumeNode(volume.get())};
    }
    case InputKind::Scene: {
        osg::ref_ptr<osg::Node> scene = readSceneFile(input.path);
        if (!isSceneRoot(*scene)) return {scene};
        osg::ref_ptr<osg::Group> group = scene->asGroup();
        if (!root && !input.placement) {  // the first scene keeps its pass (and its settings)
            root = group;
            return {};
        }
        std::vector<osg::ref_ptr<osg::Node>> children;
        for (unsigned i = 0; i < group->getNumChildren(); ++i) children.push_back(group->getChild(i));
        if (group->getStateSet()) {  // a later scene's root state stays with its own nodes
            osg::ref_ptr<osg::Group> holder = new osg::Group;
            holder->setName(osgDB::getSimpleFileName(input.path));
            holder->setStateSet(group->getStateSet());
            for (auto& child : children) holder->addChild(child);
            return {holder};
        }
        return children;
    }
    case InputKind::Model: {
        osg::ref_ptr<osg::Node> model = readSceneFile(input.path);
        osg::ref_ptr<osg::ProxyNode> proxy = new osg::ProxyNode;
        proxy->setName(osgDB::getSimpleFileName(input.path));
        proxy->setFileName(0, input.path);
        proxy->addChild(model);
        return {proxy};
    }
    }
    return {};
}

}  // namespace

osg::Matrixd Placement::matrix() const
{
    osg::Matrixd rotation;
    if (angleDegrees != 0.0) rotation.makeRotate(osg::DegreesToRadians(angleDegrees), axis);
    return osg::Matrixd::scale(scale) * rotation * osg::Matrixd::translate(translation);
}

Placement parsePlacement(const std::string& text)
{
    std::vector<std::string> fields;
    std::stringstream in(text);
    std::string field;
    while (std::getline(in, field, ':')) fields.push_back(field);
    if (fields.empty() || fields.size() > 3)
        throw std::invalid_argument("'" + text + "': expected tx,ty,tz[:scale][:axis,angle]");
    Placement p;
    const std::vector<double> t = numbers(fields[0], text);
    if (t.size() != 3) throw std::invalid_argument("'" + text + "': the translation needs tx,ty,tz");
    p.translation.set(t[0], t[1], t[2]);
    for (std::size_t f = 1; f < fields.size(); ++f) {
        std::string axisName;
        std::string rest = fields[f];
        if (!rest.empty() && (rest[0] == 'x' || rest[0] == 'y' || rest[0] == 'z') && rest.size() > 1 && rest[1] == ',') {
            axisName = rest.substr(0, 1);
            rest = rest.substr(2);
        }
        const std::vector<double> v = numbers(rest, text);
        const bool rotation = !axisName.empty() || v.size() == 4;
        if (rotation && p.angleDegrees != 0.0) throw std::invalid_argument("'" + text + "': one rotation at most");
        if (rotation) {
            if (axisName == "x") p.axis.set(1, 0, 0);
            else if (axisName == "y") p.axis.set(0, 1, 0);
            else if (axisName == "z") p.axis.set(0, 0, 1);
            else p.axis.set(v[0], v[1], v[2]);
            if ((axisName.empty() ? v.size() != 4 : v.size() != 1) || p.axis.length() == 0.0)
                throw std::invalid_argument("'" + text + "': a rotation is x|y|z,ANGLE or ax,ay,az,ANGLE (non-zero axis)");
            p.angleDegrees = v.back();
        } else if (f == 1 && (v.size() == 1 || v.size() == 3)) {
            p.scale = v.size() == 1 ? osg::Vec3d(v[0], v[0], v[0]) : osg::Vec3d(v[0], v[1], v[2]);
            if (!(p.scale.x() > 0.0 && p.scale.y() > 0.0 && p.scale.z() > 0.0))
                throw std::invalid_argument("'" + text + "': scale factors must be positive");
        } else {
            throw std::invalid_argument("'" + text + "': '" + fields[f] +
                                        "' is neither a scale (s or sx,sy,sz) nor a rotation (AXIS,ANGLE)");
        }
    }
    return p;
}

InputKind inputKind(const std::string& path)
{
    const std::string ext = osgDB::getLowerCaseFileExtension(path);
    if (ext == "osgt" || ext == "osgb" || ext == "osgx") return InputKind::Scene;
    if (isVolumeFile(path)) return InputKind::Volume;
    return InputKind::Model;
}

osg::ref_ptr<osg::Group> readSceneInputs(const std::vector<SceneInput>& inputs, const VolumeFileReader& readVolume)
{
    osg::ref_ptr<osg::Group> root;
    std::vector<osg::ref_ptr<osg::Node>> parts;
    for (const SceneInput& input : inputs) {
        std::vector<osg::ref_ptr<osg::Node>> nodes = readPart(input, readVolume, root);
        if (input.placement && !nodes.empty()) {
            osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(input.placement->matrix());
            placed->setName("placed " + osgDB::getSimpleFileName(input.path));
            for (auto& node : nodes) placed->addChild(node);
            nodes = {placed};
        }
        parts.insert(parts.end(), nodes.begin(), nodes.end());
    }
    if (!root) {
        root = makeSceneRoot();
        root->setName(inputs.size() == 1 ? "volren default scene" : "volren combined scene");
    }
    for (auto& part : parts) root->addChild(part);
    // Scene files light themselves (or leave it to the viewer's headlight, as stock viewers do).
    const bool anyScene = std::any_of(inputs.begin(), inputs.end(),
                                      [](const SceneInput& in) { return inputKind(in.path) == InputKind::Scene; });
    if (!anyScene && !hasLight(*root)) root->insertChild(0, makeHeadlight());
    return root;
}

void makeModelPathsRelative(osg::Node& scene, const std::string& folder)
{
    struct Relative : osg::NodeVisitor
    {
        explicit Relative(std::filesystem::path base) : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), base(std::move(base)) {}
        std::filesystem::path base;
        void apply(osg::ProxyNode& proxy) override
        {
            for (unsigned i = 0; i < proxy.getNumFileNames(); ++i) {
                const std::string& name = proxy.getFileName(i);
                if (name.empty()) continue;
                std::error_code ec;
                const std::filesystem::path file = std::filesystem::weakly_canonical(std::filesystem::absolute(name), ec);
                const std::filesystem::path relative = ec ? std::filesystem::path() : file.lexically_relative(base);
                if (!relative.empty()) proxy.setFileName(i, relative.generic_string());
            }
            traverse(proxy);
        }
    };
    std::error_code ec;
    std::filesystem::path base = std::filesystem::weakly_canonical(std::filesystem::absolute(folder.empty() ? "." : folder), ec);
    Relative relative(base);
    scene.accept(relative);
}

}  // namespace volren
