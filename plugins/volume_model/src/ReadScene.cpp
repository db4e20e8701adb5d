#include <volume_model/DefaultScene.h>
#include <volume_model/ReadScene.h>
#include <volume_model/ReadVolume.h>

#include <osg/Notify>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgDB/Registry>

#include <functional>
#include <sstream>
#include <stdexcept>

namespace volren {

const char* defaultSceneText();  // DefaultSceneText.cpp, generated from scenes/default.osgt

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

/// Reads a scene with `read`, turning what OSG's parser only warns about into an error.
osg::ref_ptr<osg::Node> readStrictly(const std::function<osgDB::ReaderWriter::ReadResult()>& read, const std::string& name)
{
    registerPluginPath();
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

std::string inputName(const std::string& input)
{
    return input.empty() ? std::string("the default scene (scenes/default.osgt)") : input;
}

osg::ref_ptr<osg::Node> readSceneFile(const std::string& path)
{
    if (!osgDB::fileExists(path)) throw std::runtime_error(path + ": no such file");
    return readStrictly([&] { return osgDB::Registry::instance()->readNode(path, nullptr); }, path);
}

osg::ref_ptr<osg::Node> readDefaultScene()
{
    // Its relative file names resolve in share/volren/data.
    registerPluginPath();
    osg::ref_ptr<osgDB::Options> where = new osgDB::Options;
    where->getDatabasePathList().push_back(osgDB::concatPaths(shareDirectory(), "data"));
    osgDB::ReaderWriter* osgt = osgDB::Registry::instance()->getReaderWriterForExtension("osgt");
    if (!osgt) throw std::runtime_error("OSG's osgt plugin (osgdb_osg) is missing");
    std::istringstream text(defaultSceneText());
    return readStrictly([&] { return osgt->readNode(text, where.get()); }, inputName(""));
}

}  // namespace volren
