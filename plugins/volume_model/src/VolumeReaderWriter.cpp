#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/VolumeReaderWriter.h>

#include <osgDB/FileUtils>

#include <exception>

namespace volren {

bool VolumeReaderWriter::handles(const std::string& file) const
{
    return acceptsExtension(volumeFileExtension(file));
}

std::string VolumeReaderWriter::locate(const std::string& file, const Options* options) const
{
    return handles(file) ? osgDB::findDataFile(file, options) : std::string();
}

osgDB::ReaderWriter::ReadResult VolumeReaderWriter::readObject(const std::string& file, const Options* options) const
{
    const std::string path = locate(file, options);
    if (path.empty()) return handles(file) ? ReadResult(file + ": no such file") : ReadResult(ReadResult::FILE_NOT_HANDLED);
    try {
        return readVolume(path, options);
    } catch (const std::exception& e) {
        const std::string what = e.what();
        return ReadResult(what.find(path) != std::string::npos ? what : path + ": " + what);
    }
}

osgDB::ReaderWriter::ReadResult VolumeReaderWriter::readNode(const std::string& file, const Options* options) const
{
    return asScene(readObject(file, options));
}

osgDB::ReaderWriter::ReadResult VolumeReaderWriter::asScene(ReadResult result)
{
    auto* volume = dynamic_cast<Volume*>(result.getObject());
    if (!volume) return result;
    return ReadResult(makeDefaultScene(volume).get());
}

}  // namespace volren
