// osgDB plugin for NIfTI-1 and NIfTI-2 volumes (.nii, .nii.gz): readObject gives a volren::Volume,
// readNode the default scene for it.
#include "NiftiReader.h"

#include <volume_model/DefaultScene.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <zlib.h>

#include <filesystem>
#include <istream>
#include <stdexcept>

namespace {

class ReaderWriterNIfTI : public osgDB::ReaderWriter
{
public:
    ReaderWriterNIfTI() { supportsExtension("nii", "NIfTI-1 or NIfTI-2 volume (also .nii.gz)"); }

    const char* className() const override { return "volren NIfTI-1/2 reader"; }

    ReadResult readObject(const std::string& file, const Options* options) const override
    {
        return readVolume(file, options);
    }

    ReadResult readObject(std::istream& in, const Options*) const override { return readStream(in); }

    ReadResult readNode(const std::string& file, const Options* options) const override
    {
        return asScene(readVolume(file, options));
    }

    ReadResult readNode(std::istream& in, const Options*) const override { return asScene(readStream(in)); }

private:
    static bool accepts(const std::string& file)
    {
        std::string ext = osgDB::getLowerCaseFileExtension(file);
        if (ext == "gz") ext = osgDB::getLowerCaseFileExtension(osgDB::getNameLessExtension(file));
        return ext == "nii";
    }

    static ReadResult asScene(ReadResult volumeResult)
    {
        auto* volume = dynamic_cast<volren::Volume*>(volumeResult.getObject());
        if (!volume) return volumeResult;
        return ReadResult(volren::makeDefaultScene(volume).get());
    }

    /// Most bytes `gz` can deliver: the file size when it is not compressed, else what deflate's
    /// best ratio (1032:1, with a margin) can expand the file to.
    static std::uint64_t sizeBound(gzFile gz, const std::string& path)
    {
        std::error_code ec;
        const std::uintmax_t size = std::filesystem::file_size(path, ec);
        if (ec) return volren::nifti::unknownSize;
        return gzdirect(gz) ? std::uint64_t(size) : std::uint64_t(size) * 1040 + 4096;
    }

    /// Reads .nii and .nii.gz alike: zlib reads uncompressed files transparently.
    static ReadResult readVolume(const std::string& file, const Options* options)
    {
        if (!accepts(file)) return ReadResult::FILE_NOT_HANDLED;
        const std::string path = osgDB::findDataFile(file, options);
        if (path.empty()) return ReadResult(file + ": no such file");
        gzFile gz = gzopen(path.c_str(), "rb");
        if (!gz) return ReadResult(path + ": cannot open for reading");
        gzbuffer(gz, 1 << 20);
        const volren::nifti::ByteSource source = [gz](void* dst, std::size_t size, std::string& error) -> long long {
            const int got = gzread(gz, dst, unsigned(size));
            if (got < 0) {
                int code = 0;
                error = std::string("decompression failed: ") + gzerror(gz, &code);
                return -1;
            }
            if (got == 0 && !gzeof(gz)) {
                int code = 0;
                error = std::string("read failed: ") + gzerror(gz, &code);
                return -1;
            }
            return got;
        };
        try {
            osg::ref_ptr<volren::Volume> volume = volren::nifti::readNifti(source, path, sizeBound(gz, path));
            gzclose(gz);
            return ReadResult(volume.get());
        } catch (const std::exception& e) {
            gzclose(gz);
            return ReadResult(e.what());
        }
    }

    /// Stream variant, used when OSG's own gz plugin hands over a decompressed stream.
    static ReadResult readStream(std::istream& in)
    {
        const volren::nifti::ByteSource source = [&in](void* dst, std::size_t size, std::string& error) -> long long {
            in.read(static_cast<char*>(dst), std::streamsize(size));
            if (in.bad()) {
                error = "stream read failed";
                return -1;
            }
            return in.gcount();
        };
        try {
            return ReadResult(volren::nifti::readNifti(source, "NIfTI stream").get());
        } catch (const std::exception& e) {
            return ReadResult(e.what());
        }
    }
};

}  // namespace

REGISTER_OSGPLUGIN(nii, ReaderWriterNIfTI)
