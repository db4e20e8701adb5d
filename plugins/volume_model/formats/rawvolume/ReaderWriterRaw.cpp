// osgDB plugin for headerless volumes: `.raw` (layout from reader options or FILE.raw.txt) and
// QVis/Erlangen `.dat` text headers. Built as osgdb_raw and osgdb_dat (same sources), because
// OSG finds a plugin by the file extension.
#include "PayloadVolume.h"
#include "QvisDescription.h"
#include "RawDescription.h"
#include <volume_model/VolumeReaderWriter.h>

#include <osgDB/FileNameUtils>
#include <osgDB/Registry>

namespace {

class ReaderWriterRaw : public volren::VolumeReaderWriter
{
public:
    ReaderWriterRaw()
    {
        supportsExtension("raw", "headerless volume (layout in options or FILE.raw.txt)");
        supportsExtension("dat", "QVis/Erlangen volume header + raw file");
        supportsOption("dims=X,Y,Z", ".raw: voxels along x, y, z");
        supportsOption("type=T", ".raw: uint8, int8, uint16, int16, int32, uint32 or float32");
        supportsOption("endian=E", ".raw: little (default) or big");
        supportsOption("skip=N", ".raw: header bytes before the voxels (-1: voxels at the end)");
        supportsOption("spacing=X,Y,Z", ".raw: voxel size (default 1,1,1)");
        supportsOption("channels=N", ".raw: interleaved values per voxel (default 1)");
        supportsOption("encoding=E", ".raw: raw (default) or gzip");
        supportsOption("lazy", "read: open lazily (a preview level in memory, voxels read on demand) when uncompressed, one file, one channel");
        supportsOption("ramBudgetMB=N", "read: open lazily when the voxels are larger than N MiB (default a quarter of RAM)");
    }

    const char* className() const override { return "volren raw/QVis volume reader"; }

protected:
    ReadResult readVolume(const std::string& path, const Options* options) const override
    {
        using namespace volren::rawvolume;
        const PayloadLayout layout = osgDB::getLowerCaseFileExtension(path) == "dat"
                                         ? describeQvisFile(path)
                                         : describeRawFile(path, options ? options->getOptionString() : std::string());
        return ReadResult(readPayloadVolume(layout, options).get());
    }
};

}  // namespace

// VOLREN_PLUGIN_EXT names the plugin target (raw or dat); the indirection expands it.
#define VOLREN_REGISTER_PLUGIN(ext, rw) REGISTER_OSGPLUGIN(ext, rw)
VOLREN_REGISTER_PLUGIN(VOLREN_PLUGIN_EXT, ReaderWriterRaw)
