// volren::Volume: by reference to its file (path relative to the scene file), or with its
// voxels embedded (volumes built in memory, or on request: writer option volren_embed_voxels).
#include "SceneFilePaths.h"
#include "StreamFields.h"
#include "StreamSerializer.h"

#include <volume_model/DataSearchPath.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/Volume.h>

#include <osgDB/ObjectWrapper>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <new>
#include <sstream>
#include <stdexcept>

namespace {

using namespace volren::serializers;
using volren::Volume;

/// Writer option (in Options::getOptionString) that embeds voxels even when there is a file.
const char* const embedOption = "volren_embed_voxels";
/// Bytes per hex line in text files.
constexpr std::size_t hexBytesPerLine = 64;
/// Largest block handed to the binary stream at once.
constexpr std::size_t binaryChunk = std::size_t(1) << 30;

bool embedRequested(const osgDB::Options* options)
{
    if (!options) return false;
    std::istringstream words(options->getOptionString());
    for (std::string word; words >> word;)
        if (word == embedOption) return true;
    return false;
}

/// Options for the volume reader: the scene's search paths and progress, not its format options.
osg::ref_ptr<osgDB::Options> volumeReaderOptions(const osgDB::Options* sceneOptions)
{
    osg::ref_ptr<osgDB::Options> options =
        sceneOptions ? static_cast<osgDB::Options*>(sceneOptions->clone(osg::CopyOp::SHALLOW_COPY)) : new osgDB::Options;
    options->setOptionString(std::string());
    options->removePluginStringData("fileType");
    return options;
}

// --- Voxels: type, dims, channels, frames and the stored bytes (host byte order) ---------

bool checkVoxels(const osgDB::OutputStream& os, const Volume& volume)
{
    return volume.voxelCount() > 0 && (volume.sourceFile.empty() || embedRequested(os.getOptions()));
}

bool writeVoxels(osgDB::OutputStream& os, const Volume& volume)
{
    os << os.BEGIN_BRACKET << std::endl;
    writeProperty(os, "Type");
    os << std::string(volren::voxelTypeName(volume.type())) << std::endl;
    writeProperty(os, "Dims");
    for (int i = 0; i < 3; ++i) writeInt(os, volume.dims()[i]);
    os << std::endl;
    writeProperty(os, "Channels");
    writeInt(os, volume.channels());
    os << std::endl;
    writeProperty(os, "Frames");
    writeInt(os, volume.frames());
    os << std::endl;
    writeProperty(os, "Bytes");
    writeInt(os, std::int64_t(volume.byteSize()));
    os << os.BEGIN_BRACKET << std::endl;
    const std::uint8_t* bytes = volume.block(0, 0);
    const std::size_t size = volume.byteSize();
    if (os.isBinary()) {
        for (std::size_t done = 0; done < size; done += binaryChunk)
            os.writeCharArray(reinterpret_cast<const char*>(bytes + done), unsigned(std::min(binaryChunk, size - done)));
    } else {
        static const char digits[] = "0123456789abcdef";
        std::string line;
        for (std::size_t done = 0; done < size; done += hexBytesPerLine) {
            line.clear();
            for (std::size_t i = done; i < std::min(size, done + hexBytesPerLine); ++i) {
                line += digits[bytes[i] >> 4];
                line += digits[bytes[i] & 15];
            }
            os << line << std::endl;
        }
    }
    os << os.END_BRACKET << std::endl;
    os << os.END_BRACKET << std::endl;
    return true;
}

int hexDigit(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

bool readHexBytes(osgDB::InputStream& is, std::vector<std::uint8_t>& bytes)
{
    std::size_t filled = 0;
    std::string token;
    while (filled < bytes.size()) {
        is >> token;
        if (is.getException()) return false;
        if (token.size() % 2 || token.size() / 2 > bytes.size() - filled)
            return fail(is, "volren::Volume Voxels: bad voxel data line '" + token.substr(0, 16) + "...' after " +
                                std::to_string(filled) + " of " + std::to_string(bytes.size()) + " bytes"),
                   false;
        for (std::size_t i = 0; i < token.size(); i += 2) {
            const int hi = hexDigit(token[i]), lo = hexDigit(token[i + 1]);
            if (hi < 0 || lo < 0)
                return fail(is, "volren::Volume Voxels: '" + token.substr(i, 2) + "' is not a hex byte"), false;
            bytes[filled++] = std::uint8_t(hi * 16 + lo);
        }
    }
    return true;
}

bool readVoxels(osgDB::InputStream& is, Volume& volume)
{
    const std::string field = "volren::Volume Voxels";
    is >> is.BEGIN_BRACKET;
    if (!readProperty(is, "Type", field)) return false;
    std::string typeName;
    if (!readString(is, typeName, field + " Type")) return false;
    volren::VoxelType type{};
    if (!volren::parseVoxelType(typeName, type)) return fail(is, field + ": unknown voxel type '" + typeName + "'"), false;
    std::int64_t dims[3] = {0, 0, 0}, channels = 0, frames = 0, byteCount = 0;
    if (!readProperty(is, "Dims", field)) return false;
    for (std::int64_t& d : dims)
        if (!readInt(is, d, 1, INT_MAX, field + " Dims")) return false;
    if (!readProperty(is, "Channels", field) || !readInt(is, channels, 1, INT_MAX, field + " Channels")) return false;
    if (!readProperty(is, "Frames", field) || !readInt(is, frames, 1, INT_MAX, field + " Frames")) return false;
    if (!readProperty(is, "Bytes", field) || !readInt(is, byteCount, 0, std::int64_t(1) << 53, field + " Bytes"))
        return false;
    const osg::Vec3i size{int(dims[0]), int(dims[1]), int(dims[2])};
    std::vector<std::uint8_t> bytes;
    try {
        const std::uint64_t voxels = Volume::checkedVoxelCount(size, std::uint64_t(channels) * std::uint64_t(frames));
        if (voxels * volren::voxelSize(type) != std::uint64_t(byteCount))
            return fail(is, field + ": " + std::to_string(byteCount) + " bytes given, " + std::to_string(voxels) + " " +
                                typeName + " voxels need " + std::to_string(voxels * volren::voxelSize(type))),
                   false;
        bytes.resize(std::size_t(byteCount));
    } catch (const std::bad_alloc&) {
        return fail(is, field + ": out of memory for " + std::to_string(byteCount) + " bytes"), false;
    } catch (const std::exception& e) {
        return fail(is, field + ": " + e.what()), false;
    }
    is >> is.BEGIN_BRACKET;
    if (is.isBinary()) {
        for (std::size_t done = 0; done < bytes.size(); done += binaryChunk)
            is.readCharArray(reinterpret_cast<char*>(bytes.data() + done), unsigned(std::min(binaryChunk, bytes.size() - done)));
    } else if (!readHexBytes(is, bytes)) {
        return false;
    }
    is >> is.END_BRACKET;
    is >> is.END_BRACKET;
    if (is.getException()) return false;
    try {
        volume.assign(type, size, std::move(bytes), int(channels), int(frames));
    } catch (const std::exception& e) {
        return fail(is, field + ": " + e.what()), false;
    }
    return true;
}

// --- SourceFile: the volume file, relative to the scene file ------------------------------

bool checkSourceFile(const Volume& volume) { return !volume.sourceFile.empty(); }

bool writeSourceFile(osgDB::OutputStream& os, const Volume& volume)
{
    writeString(os, pathForScene(volume.sourceFile, os.getOptions()));
    os << std::endl;
    return true;
}

bool readSourceFile(osgDB::InputStream& is, Volume& volume)
{
    std::string path;
    if (!readString(is, path, "volren::Volume SourceFile")) return false;
    const std::string found = resolveFromScene(path, is.getOptions());
    if (volume.voxelCount() > 0) {  // embedded voxels were read: the file is only a note
        volume.sourceFile = found.empty() ? path : found;
        return true;
    }
    const std::string field = "volren::Volume SourceFile";
    if (found.empty()) {
        const std::string folder = sceneFolder(is.getOptions());
        return fail(is, field + ": volume file '" + path + "' not found (looked in " + volren::searchedFolders(folder) +
                            "; set OSG_FILE_PATH to the folder holding it)"),
               false;
    }
    try {
        osg::ref_ptr<Volume> loaded = volren::readVolumeFile(found, volumeReaderOptions(is.getOptions()).get());
        std::vector<std::uint8_t> bytes(loaded->block(0, 0), loaded->block(0, 0) + loaded->byteSize());
        volume.assign(loaded->type(), loaded->dims(), std::move(bytes), loaded->channels(), loaded->frames());
        volume.setSpacing(loaded->spacing());
        volume.setRescale(loaded->rescaleSlope(), loaded->rescaleIntercept());
        volume.sourceFile = found;
    } catch (const std::bad_alloc&) {
        return fail(is, field + ": out of memory reading '" + found + "'"), false;
    } catch (const std::exception& e) {
        return fail(is, field + " '" + path + "': " + e.what()), false;
    }
    return true;
}

// --- Spacing and Rescale: always written, so edits after loading a file survive ----------

bool checkSpacing(const Volume&) { return true; }

bool writeSpacing(osgDB::OutputStream& os, const Volume& volume)
{
    for (int i = 0; i < 3; ++i) writeDouble(os, volume.spacing()[i]);
    os << std::endl;
    return true;
}

bool readSpacing(osgDB::InputStream& is, Volume& volume)
{
    osg::Vec3d spacing;
    for (int i = 0; i < 3; ++i)
        if (!readDouble(is, spacing[i], "volren::Volume Spacing")) return false;
    try {
        volume.setSpacing(spacing);
    } catch (const std::exception& e) {
        return fail(is, std::string("volren::Volume Spacing: ") + e.what()), false;
    }
    return true;
}

bool checkRescale(const Volume&) { return true; }

bool writeRescale(osgDB::OutputStream& os, const Volume& volume)
{
    writeDouble(os, volume.rescaleSlope());
    writeDouble(os, volume.rescaleIntercept());
    os << std::endl;
    return true;
}

bool readRescale(osgDB::InputStream& is, Volume& volume)
{
    double slope = 1.0, intercept = 0.0;
    if (!readDouble(is, slope, "volren::Volume Rescale") || !readDouble(is, intercept, "volren::Volume Rescale"))
        return false;
    try {
        volume.setRescale(slope, intercept);
    } catch (const std::exception& e) {
        return fail(is, std::string("volren::Volume Rescale: ") + e.what()), false;
    }
    return true;
}

}  // namespace

/// A Volume needs its voxels from somewhere: a scene that names neither a file nor voxels fails.
struct RequireVoxels : osgDB::FinishedObjectReadCallback
{
    void objectRead(osgDB::InputStream& is, osg::Object& object) override
    {
        if (is.getException()) return;
        if (static_cast<Volume&>(object).voxelCount() == 0)
            fail(is, "volren::Volume '" + object.getName() + "': no SourceFile and no Voxels (an empty volume)");
    }
};

REGISTER_OBJECT_WRAPPER(volren_Volume, new volren::Volume, volren::Volume, "osg::Object volren::Volume")
{
    wrapper->addFinishedObjectReadCallback(new RequireVoxels);
    // Voxels before SourceFile: embedded voxels win, and the file is then not read.
    wrapper->addSerializer(new StreamSerializer<Volume>("Voxels", &checkVoxels, &readVoxels, &writeVoxels),
                           osgDB::BaseSerializer::RW_USER);
    ADD_USER_SERIALIZER(SourceFile);
    ADD_USER_SERIALIZER(Spacing);  // after SourceFile: overrides the file's own values
    ADD_USER_SERIALIZER(Rescale);
}
