// osgDB plugin for MetaImage volumes: `.mhd` (detached data) and `.mha` (LOCAL data). Built as
// osgdb_mhd and osgdb_mha (same sources), because OSG finds a plugin by the file extension.
#include "MetaImageDescription.h"

#include <volume_model/VolumeReaderWriter.h>

#include <osgDB/Registry>

namespace {

class ReaderWriterMetaImage : public volren::VolumeReaderWriter
{
public:
    ReaderWriterMetaImage()
    {
        supportsExtension("mhd", "MetaImage header with detached data");
        supportsExtension("mha", "MetaImage with attached data");
        supportsOption("lazy", "read: open lazily (a preview level in memory, voxels read on demand) when uncompressed, one file, one channel");
        supportsOption("ramBudgetMB=N", "read: open lazily when the voxels are larger than N MiB (default a quarter of RAM)");
    }

    const char* className() const override { return "volren MetaImage reader"; }

protected:
    ReadResult readVolume(const std::string& path, const Options* options) const override
    {
        return ReadResult(volren::rawvolume::readPayloadVolume(volren::metaimage::describeMetaImageFile(path), options).get());
    }
};

}  // namespace

// VOLREN_PLUGIN_EXT names the plugin target (mhd or mha); the indirection expands it.
#define VOLREN_REGISTER_PLUGIN(ext, rw) REGISTER_OSGPLUGIN(ext, rw)
VOLREN_REGISTER_PLUGIN(VOLREN_PLUGIN_EXT, ReaderWriterMetaImage)
