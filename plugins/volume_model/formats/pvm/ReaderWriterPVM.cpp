// osgDB plugin for PVM volumes (Roettger's V^3 format, uncompressed): readObject gives a
// volren::Volume, readNode the default scene for it.
#include "PvmReader.h"

#include <volume_model/LoadProgress.h>
#include <volume_model/VolumeReaderWriter.h>

#include <osgDB/Registry>

#include <fstream>
#include <stdexcept>

namespace {

class ReaderWriterPVM : public volren::VolumeReaderWriter
{
public:
    ReaderWriterPVM() { supportsExtension("pvm", "PVM volume (V^3 library), uncompressed"); }

    const char* className() const override { return "volren PVM reader"; }

protected:
    ReadResult readVolume(const std::string& path, const Options* options) const override
    {
        std::ifstream in(path, std::ios::binary | std::ios::ate);
        if (!in) return ReadResult(path + ": cannot open for reading");
        const std::streamoff size = in.tellg();
        if (size < 0) return ReadResult(path + ": cannot determine the file size");
        std::vector<std::uint8_t> bytes;
        try {
            bytes.resize(std::size_t(size));
        } catch (const std::exception&) {
            return ReadResult(path + ": not enough memory to read " + std::to_string(size) + " bytes");
        }
        in.seekg(0);
        if (!in.read(reinterpret_cast<char*>(bytes.data()), size)) return ReadResult(path + ": read failed");
        if (!volren::reportLoadProgress(options, 1.0, 2.0)) return ReadResult(path + ": cancelled");
        osg::ref_ptr<volren::Volume> volume = volren::pvm::readPvm(bytes, path);
        if (!volren::reportLoadProgress(options, 2.0, 2.0)) return ReadResult(path + ": cancelled");
        return ReadResult(volume.get());
    }
};

}  // namespace

REGISTER_OSGPLUGIN(pvm, ReaderWriterPVM)
