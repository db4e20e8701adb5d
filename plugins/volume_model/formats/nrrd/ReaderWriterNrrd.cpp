// osgDB plugin for NRRD volumes: `.nrrd` (attached or detached data) and `.nhdr` (detached
// header) reading, `.nrrd` writing. Built as osgdb_nrrd and osgdb_nhdr (same sources),
// because OSG finds a plugin by the file extension.
#include "NrrdDescription.h"
#include "NrrdWriter.h"

#include <volume_model/VolumeReaderWriter.h>

#include <osgDB/FileNameUtils>
#include <osgDB/Registry>

#include <sstream>
#include <stdexcept>

namespace {

class ReaderWriterNrrd : public volren::VolumeReaderWriter
{
public:
    ReaderWriterNrrd()
    {
        supportsExtension("nrrd", "NRRD volume (attached or detached data)");
        supportsExtension("nhdr", "NRRD detached header");
        supportsOption("encoding=gzip", "write: gzip-compressed voxels (default)");
        supportsOption("encoding=raw", "write: uncompressed voxels");
        supportsOption("lazy", "read: open lazily (a preview level in memory, voxels read on demand) when uncompressed, one file, one channel");
        supportsOption("ramBudgetMB=N", "read: open lazily when the voxels are larger than N MiB (default a quarter of RAM)");
    }

    const char* className() const override { return "volren NRRD reader/writer"; }

    WriteResult writeObject(const osg::Object& object, const std::string& file, const Options* options) const override
    {
        if (osgDB::getLowerCaseFileExtension(file) != "nrrd") return WriteResult::FILE_NOT_HANDLED;
        const auto* volume = dynamic_cast<const volren::Volume*>(&object);
        if (!volume) return WriteResult(file + ": only a volren::Volume can be written as NRRD");
        bool gzip = true;
        std::istringstream words(options ? options->getOptionString() : std::string());
        for (std::string word; words >> word;)
            if (word == "encoding=raw") gzip = false;
            else if (word == "encoding=gzip") gzip = true;
        try {
            volren::nrrd::writeNrrd(*volume, file, gzip);
        } catch (const std::exception& e) {
            return WriteResult(e.what());
        }
        return WriteResult::FILE_SAVED;
    }

protected:
    ReadResult readVolume(const std::string& path, const Options* options) const override
    {
        return ReadResult(volren::rawvolume::readPayloadVolume(volren::nrrd::describeNrrdFile(path), options).get());
    }
};

}  // namespace

// VOLREN_PLUGIN_EXT names the plugin target (nrrd or nhdr); the indirection expands it.
#define VOLREN_REGISTER_PLUGIN(ext, rw) REGISTER_OSGPLUGIN(ext, rw)
VOLREN_REGISTER_PLUGIN(VOLREN_PLUGIN_EXT, ReaderWriterNrrd)
