// osgDB plugin for OME-Zarr 0.4 images (zarr v2 folders named `x.ome.zarr` or `x.zarr`):
// readObject gives one resolution level as a volren::Volume (option level=N), readNode its
// default scene, writeObject writes a volume as a multiscale pyramid.
#include "OmeZarrVolume.h"
#include "OmeZarrWriter.h"

#include <volume_model/LazyOpening.h>
#include <volume_model/VolumeReaderWriter.h>

#include <osg/Notify>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <optional>
#include <sstream>
#include <stdexcept>

namespace {

std::string withoutTrailingSlash(std::string path)
{
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    return path;
}

/// The level=N word of `options`, if any.
std::optional<std::size_t> levelOption(const osgDB::Options* options)
{
    std::istringstream words(options ? options->getOptionString() : std::string());
    std::optional<std::size_t> level;
    for (std::string word; words >> word;) {
        if (word.rfind("level=", 0) != 0) continue;
        const std::string value = word.substr(6);
        if (value.empty() || value.size() > 3 || value.find_first_not_of("0123456789") != std::string::npos)
            throw std::runtime_error("option " + word + ": the level must be a whole number (0 = finest)");
        level = std::stoul(value);
    }
    return level;
}

class ReaderWriterOmeZarr : public volren::VolumeReaderWriter
{
public:
    ReaderWriterOmeZarr()
    {
        supportsExtension("zarr", "OME-Zarr 0.4 image (zarr v2 folder, x.ome.zarr), read and written");
        supportsOption("level=N", "read: resolution level N of the multiscale pyramid (0 = finest, the default)");
        supportsOption("lazy", "read: open lazily (a preview level in memory, every level read on demand), channel 0 and time point 0 only");
        supportsOption("ramBudgetMB=N", "read: open lazily when level 0 is larger than N MiB (default a quarter of RAM); level=N reads whole");
        supportsOption("chunk=N", "write: chunk edge along z, y, x (default 64)");
        supportsOption("compression=NAME",
                       "write: blosc-lz4 (default, byte shuffle), blosc-lz4hc, blosc-zstd, blosc-zlib, blosc-blosclz, zlib, gzip or none");
    }

    const char* className() const override { return "volren OME-Zarr reader/writer"; }

    WriteResult writeObject(const osg::Object& object, const std::string& file, const Options* options) const override
    {
        const std::string path = withoutTrailingSlash(file);
        if (osgDB::getLowerCaseFileExtension(path) != "zarr") return WriteResult::FILE_NOT_HANDLED;
        const auto* volume = dynamic_cast<const volren::Volume*>(&object);
        if (!volume) return WriteResult(path + ": only a volren::Volume can be written as OME-Zarr");
        try {
            const volren::omezarr::WriteSettings settings =
                volren::omezarr::parseWriteSettings(options ? options->getOptionString() : std::string());
            volren::omezarr::writeOmeZarr(*volume, path, settings, options);
        } catch (const std::exception& e) {
            const std::string what = e.what();
            return WriteResult(what.find(path) != std::string::npos ? what : path + ": " + what);
        }
        return WriteResult::FILE_SAVED;
    }

protected:
    /// Folders named *.zarr, or any folder with zarr metadata at its top (e.g. `image/`).
    std::string locate(const std::string& file, const Options* options) const override
    {
        const std::string path = withoutTrailingSlash(file);
        const bool zarrMetadata = osgDB::fileExists(path + "/.zattrs") || osgDB::fileExists(path + "/.zgroup") ||
                                  osgDB::fileExists(path + "/.zarray");
        if (!handles(path) && !zarrMetadata) return {};
        if (osgDB::fileType(path) == osgDB::DIRECTORY) return path;
        return osgDB::findDataFile(path, options);
    }

    ReadResult readVolume(const std::string& path, const Options* options) const override
    {
        const std::optional<std::size_t> level = levelOption(options);
        const volren::LazyOpening lazy = volren::lazyOpeningOf(options);
        if (lazy.requested || (!level && volren::omezarr::omeZarrLevelBytes(path, 0) > lazy.ramBudget)) {
            if (level) OSG_NOTICE << path << ": option level=" << *level << " is ignored when opening lazily" << std::endl;
            return ReadResult(volren::omezarr::openOmeZarrVolumeLazily(path, lazy.previewBudget(), lazy.chunkCacheBudget(), options).get());
        }
        return ReadResult(volren::omezarr::readOmeZarrVolume(path, level.value_or(0), options).get());
    }
};

}  // namespace

REGISTER_OSGPLUGIN(zarr, ReaderWriterOmeZarr)
