// osgDB plugin for stacks of 2D images (PNG, JPEG, ... through OpenImageIO): a `.imgstack`
// list file or a directory of numbered images gives a volren::Volume (readObject) or the
// default scene for it (readNode). Option string: `spacing=x,y,z`.
#include "ImageList.h"
#include "ImageStackReader.h"
#include "NumberedFiles.h"

#include <volume_model/VolumeReaderWriter.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <stdexcept>

namespace {

class ReaderWriterImageStack : public volren::VolumeReaderWriter
{
public:
    ReaderWriterImageStack() { supportsExtension("imgstack", "list of 2D images (one path per line) stacked along z"); }

    const char* className() const override { return "volren image stack reader"; }

protected:
    /// A directory of numbered images, or a `.imgstack` list.
    std::string locate(const std::string& file, const Options* options) const override
    {
        return osgDB::fileType(file) == osgDB::DIRECTORY ? file : VolumeReaderWriter::locate(file, options);
    }

    ReadResult readVolume(const std::string& path, const Options* options) const override
    {
        const std::vector<std::string> images =
            osgDB::fileType(path) == osgDB::DIRECTORY
                ? volren::stack::numberedFiles(path, volren::imagestack::imageExtensions())
                : volren::imagestack::readImageList(path);
        return ReadResult(volren::imagestack::readImageStack(images, path, options).get());
    }
};

}  // namespace

REGISTER_OSGPLUGIN(imgstack, ReaderWriterImageStack)
