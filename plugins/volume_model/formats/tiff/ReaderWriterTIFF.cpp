// osgDB plugin for TIFF stacks: readObject gives a volren::Volume (multi-page TIFF, ImageJ
// hyperstack, OME-TIFF, or a directory / wildcard pattern of numbered 2D slices), readNode the
// default scene for it, readImage the same voxels as an osg::Image.
#include "NumberedFiles.h"
#include "TiffStackReader.h"
#include "VolumeImage.h"

#include <volume_model/VolumeReaderWriter.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <stdexcept>

namespace {

class ReaderWriterTIFF : public volren::VolumeReaderWriter
{
public:
    ReaderWriterTIFF()
    {
        supportsExtension("tif", "TIFF stack as a volume (multi-page, ImageJ, OME-TIFF)");
        supportsExtension("tiff", "TIFF stack as a volume (multi-page, ImageJ, OME-TIFF)");
    }

    const char* className() const override { return "volren TIFF stack reader"; }

    ReadResult readImage(const std::string& file, const Options* options) const override
    {
        ReadResult result = readObject(file, options);
        auto* volume = dynamic_cast<volren::Volume*>(result.getObject());
        if (!volume) return result;
        osg::ref_ptr<osg::Image> image = volren::tiff::volumeAsImage(*volume);
        if (!image) return ReadResult(file + ": " + std::to_string(volume->channels()) + " channels do not make an image");
        return ReadResult(image.get());
    }

protected:
    /// A directory of numbered slices, a pattern of them ("s*.tif"), or one (multi-page) file.
    std::string locate(const std::string& file, const Options* options) const override
    {
        if (osgDB::fileType(file) == osgDB::DIRECTORY || (handles(file) && volren::stack::isFilePattern(file))) return file;
        return VolumeReaderWriter::locate(file, options);
    }

    ReadResult readVolume(const std::string& path, const Options* options) const override
    {
        static const std::vector<std::string> extensions{"tif", "tiff"};
        const bool several = osgDB::fileType(path) == osgDB::DIRECTORY || volren::stack::isFilePattern(path);
        const std::vector<std::string> files = several ? volren::stack::numberedFiles(path, extensions)
                                                       : std::vector<std::string>{path};
        return ReadResult(volren::tiff::readTiffStack(files, path, options).get());
    }
};

}  // namespace

REGISTER_OSGPLUGIN(tiff, ReaderWriterTIFF)
