#include "OmeZarrWriter.h"

#include "MeanPyramid.h"
#include "OmeZarrVolume.h"

#include <volume_model/ChannelDisplay.h>
#include <volume_model/LoadProgress.h>
#include <volume_model/ZarrCodec.h>

#include <osgDB/FileNameUtils>
#include <nlohmann/json.hpp>

#include <bit>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace volren::omezarr {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

/// OME-NGFF's name of a length unit symbol ("µm" -> "micrometer"), or "" for units it has none for.
std::string ngffLengthUnit(const std::string& symbol)
{
    static const std::map<std::string, std::string> names = {{"nm", "nanometer"}, {"\xC2\xB5m", "micrometer"},
                                                             {"mm", "millimeter"}, {"cm", "centimeter"},
                                                             {"m", "meter"}};
    const auto it = names.find(symbol);
    return it == names.end() ? std::string() : it->second;
}

ZarrDataType dataTypeOf(VoxelType type)
{
    ZarrDataType t;
    t.size = int(voxelSize(type));
    t.kind = type == VoxelType::Float32 ? 'f' : (type == VoxelType::Int8 || type == VoxelType::Int16) ? 'i' : 'u';
    t.byteOrder = t.size == 1 ? '|' : (std::endian::native == std::endian::big) ? '>' : '<';
    return t;
}

void writeFile(const fs::path& file, const void* data, std::size_t size)
{
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out || !out.write(static_cast<const char*>(data), std::streamsize(size)) || !out.flush())
        throw std::runtime_error(file.string() + ": write failed: " + std::strerror(errno));
}

void writeText(const fs::path& file, const std::string& text)
{
    writeFile(file, text.data(), text.size());
}

/// Whether `path` is a folder the writer may replace: empty, or made by a zarr writer (zarr
/// metadata at its top).
bool isReplaceableFolder(const fs::path& path)
{
    std::error_code ec;
    return fs::is_directory(path, ec) && (fs::is_empty(path, ec) || fs::exists(path / ".zgroup", ec) ||
                                          fs::exists(path / ".zattrs", ec) || fs::exists(path / ".zarray", ec));
}

/// Dimensions of every pyramid level: halving until every axis fits in one chunk.
std::vector<osg::Vec3i> levelDims(const osg::Vec3i& dims, std::uint64_t chunk)
{
    std::vector<osg::Vec3i> levels{dims};
    const auto fits = [chunk](const osg::Vec3i& d) {
        return std::uint64_t(d.x()) <= chunk && std::uint64_t(d.y()) <= chunk && std::uint64_t(d.z()) <= chunk;
    };
    while (!fits(levels.back())) {
        const osg::Vec3i& d = levels.back();
        levels.push_back(osg::Vec3i((d.x() + 1) / 2, (d.y() + 1) / 2, (d.z() + 1) / 2));
    }
    return levels;
}

std::uint64_t chunksOf(const osg::Vec3i& d, std::uint64_t chunk)
{
    const auto n = [chunk](int size) { return (std::uint64_t(size) + chunk - 1) / chunk; };
    return n(d.x()) * n(d.y()) * n(d.z());
}

/// The folder's contents, built under `tmp`.
class PyramidWriter
{
public:
    PyramidWriter(const Volume& volume, const fs::path& tmp, const WriteSettings& settings, const osgDB::Options* options,
                  const std::string& name)
        : _volume(volume), _tmp(tmp), _settings(settings), _options(options), _name(name)
    {
        _time = volume.frames() > 1;
        _channel = volume.channels() > 1;
    }

    void write()
    {
        const std::vector<osg::Vec3i> dims = levelDims(_volume.dims(), _settings.chunk);
        for (const osg::Vec3i& d : dims) _totalChunks += chunksOf(d, _settings.chunk) * std::uint64_t(_volume.channels() * _volume.frames());
        fs::create_directory(_tmp);
        writeText(_tmp / ".zgroup", "{\n    \"zarr_format\": 2\n}\n");
        const Volume* level = &_volume;  // the caller's volume, then each coarser level made here
        osg::ref_ptr<Volume> coarser;
        Json datasets = Json::array();
        for (std::size_t l = 0; l < dims.size(); ++l) {
            if (l > 0) {
                coarser = halveByMean(*level);
                level = coarser.get();
            }
            writeLevel(*level, std::to_string(l));
            datasets.push_back({{"path", std::to_string(l)}, {"coordinateTransformations", transforms(*level)}});
        }
        writeText(_tmp / ".zattrs", attributes(datasets).dump(4) + "\n");
    }

private:
    /// Per axis (t, c, z, y, x as present): scale, and translation that centres the voxels.
    Json transforms(const Volume& level) const
    {
        const osg::Vec3d& s = level.spacing();
        const osg::Vec3d& s0 = _volume.spacing();
        std::vector<double> scale, translation;
        if (_time) {
            double step = 1.0;
            _volume.getUserValue(timeStepKey, step);
            scale.push_back(step);
            translation.push_back(0.0);
        }
        if (_channel) {
            scale.push_back(1.0);
            translation.push_back(0.0);
        }
        for (int axis : {2, 1, 0}) {
            scale.push_back(s[axis]);
            translation.push_back(0.5 * (s[axis] - s0[axis]));  // voxel i covers voxels [2i, 2i+2) of the level before
        }
        return Json::array({{{"type", "scale"}, {"scale", scale}}, {{"type", "translation"}, {"translation", translation}}});
    }

    Json attributes(const Json& datasets) const
    {
        std::string timeUnit;
        const std::string spaceUnit = ngffLengthUnit(lengthUnitOf(_volume));  // "" where NGFF has no name for it
        _volume.getUserValue(timeUnitKey, timeUnit);
        Json axes = Json::array();
        const auto axis = [&](const char* name, const char* type, const std::string& unit) {
            Json a = {{"name", name}, {"type", type}};
            if (!unit.empty()) a["unit"] = unit;
            axes.push_back(a);
        };
        if (_time) axis("t", "time", timeUnit);
        if (_channel) axis("c", "channel", "");
        for (const char* name : {"z", "y", "x"}) axis(name, "space", spaceUnit);
        Json multiscale = {{"version", "0.4"},
                           {"name", osgDB::getSimpleFileName(_volume.sourceFile.empty() ? _name : _volume.sourceFile)},
                           {"axes", axes},
                           {"datasets", datasets},
                           {"type", "mean"},
                           {"metadata", {{"method", "volren: mean of 2x2x2 voxels, rounded to the voxel type"}}}};
        Json root = {{"multiscales", Json::array({multiscale})}};
        if (_channel) root["omero"] = omero();
        if (_volume.rescaleSlope() != 1.0 || _volume.rescaleIntercept() != 0.0)
            root["volren"] = {{"rescale", {_volume.rescaleSlope(), _volume.rescaleIntercept()}}};
        return root;
    }

    /// omero display hints for several channels: a colour each (the file's brightest, else the
    /// fluorescence palette's), the channel's value range and its display window (the file's, else the range).
    Json omero() const
    {
        auto hex = [](const osg::Vec3f& c) {
            char text[8];
            std::snprintf(text, sizeof text, "%02X%02X%02X", int(std::lround(std::clamp(c.x(), 0.f, 1.f) * 255)),
                          int(std::lround(std::clamp(c.y(), 0.f, 1.f) * 255)), int(std::lround(std::clamp(c.z(), 0.f, 1.f) * 255)));
            return std::string(text);
        };
        Json channels = Json::array();
        const std::size_t n = _volume.voxelCount();
        for (int c = 0; c < _volume.channels(); ++c) {
            double lo = 0.0, hi = 0.0;
            bool any = false;
            const std::size_t base = std::size_t(c) * n;  // frame 0
            for (std::size_t i = 0; i < n; ++i) {
                const double v = _volume.storedValue(base + i);
                if (!std::isfinite(v)) continue;
                lo = any ? std::min(lo, v) : v;
                hi = any ? std::max(hi, v) : v;
                any = true;
            }
            const ChannelHint* hint =
                std::size_t(c) < _volume.channelHints.size() ? &_volume.channelHints[std::size_t(c)] : nullptr;
            double start = lo, end = hi;
            if (hint && hint->hasWindow && _volume.rescaleSlope() != 0.0) {  // data values back to stored ones
                start = (hint->low - _volume.rescaleIntercept()) / _volume.rescaleSlope();
                end = (hint->high - _volume.rescaleIntercept()) / _volume.rescaleSlope();
                if (start > end) std::swap(start, end);
            }
            channels.push_back({{"label", hint && !hint->name.empty() ? hint->name : "channel " + std::to_string(c)},
                                {"color", hex(hint && !hint->colours.empty() ? hint->colours.back() : channelColour(c))},
                                {"active", !hint || hint->visible},
                                {"window", {{"min", lo}, {"max", hi}, {"start", start}, {"end", end}}}});
        }
        return {{"channels", channels}, {"rdefs", {{"model", "color"}}}};
    }

    void writeLevel(const Volume& level, const std::string& folder)
    {
        const osg::Vec3i& d = level.dims();
        const std::uint64_t cx = std::min<std::uint64_t>(_settings.chunk, std::uint64_t(d.x()));
        const std::uint64_t cy = std::min<std::uint64_t>(_settings.chunk, std::uint64_t(d.y()));
        const std::uint64_t cz = std::min<std::uint64_t>(_settings.chunk, std::uint64_t(d.z()));
        ZarrArrayMetadata m;
        if (_time) {
            m.shape.push_back(std::uint64_t(level.frames()));
            m.chunks.push_back(1);
        }
        if (_channel) {
            m.shape.push_back(std::uint64_t(level.channels()));
            m.chunks.push_back(1);
        }
        for (std::uint64_t s : {std::uint64_t(d.z()), std::uint64_t(d.y()), std::uint64_t(d.x())}) m.shape.push_back(s);
        for (std::uint64_t c : {cz, cy, cx}) m.chunks.push_back(c);
        m.dtype = dataTypeOf(level.type());
        m.compressor = _settings.compressor;
        m.separator = '/';
        const fs::path dir = _tmp / folder;
        fs::create_directory(dir);
        writeText(dir / ".zarray", m.toJson());

        const std::size_t vb = voxelSize(level.type());
        std::vector<std::uint8_t> chunk(std::size_t(cx * cy * cz) * vb);
        const std::size_t nx = std::size_t(d.x()), nxy = nx * std::size_t(d.y());
        for (int t = 0; t < level.frames(); ++t)
            for (int c = 0; c < level.channels(); ++c) {
                const std::uint8_t* block = level.block(c, t);
                for (std::uint64_t z0 = 0; z0 < std::uint64_t(d.z()); z0 += cz)
                    for (std::uint64_t y0 = 0; y0 < std::uint64_t(d.y()); y0 += cy)
                        for (std::uint64_t x0 = 0; x0 < std::uint64_t(d.x()); x0 += cx) {
                            // zarr v2 stores edge chunks at full size; the padding is the fill value 0.
                            std::fill(chunk.begin(), chunk.end(), std::uint8_t(0));
                            const std::uint64_t row = std::min<std::uint64_t>(cx, std::uint64_t(d.x()) - x0);
                            for (std::uint64_t z = z0; z < std::min<std::uint64_t>(z0 + cz, std::uint64_t(d.z())); ++z)
                                for (std::uint64_t y = y0; y < std::min<std::uint64_t>(y0 + cy, std::uint64_t(d.y())); ++y)
                                    std::memcpy(chunk.data() + (((z - z0) * cy + (y - y0)) * cx) * vb,
                                                block + (z * nxy + y * nx + x0) * vb, std::size_t(row) * vb);
                            const std::vector<std::uint8_t> encoded = encodeZarrChunk(chunk.data(), chunk.size(), vb, m.compressor);
                            std::vector<std::uint64_t> index;
                            if (_time) index.push_back(std::uint64_t(t));
                            if (_channel) index.push_back(std::uint64_t(c));
                            for (std::uint64_t i : {z0 / cz, y0 / cy, x0 / cx}) index.push_back(i);
                            const fs::path file = dir / m.chunkKey(index);
                            fs::create_directories(file.parent_path());
                            writeFile(file, encoded.data(), encoded.size());
                            if (!reportLoadProgress(_options, double(++_doneChunks), double(_totalChunks)))
                                throw std::runtime_error(_name + ": cancelled");
                        }
            }
    }

    const Volume& _volume;
    fs::path _tmp;
    WriteSettings _settings;
    const osgDB::Options* _options;
    std::string _name;
    bool _time = false, _channel = false;
    std::uint64_t _totalChunks = 0, _doneChunks = 0;
};

}  // namespace

WriteSettings parseWriteSettings(const std::string& optionString)
{
    WriteSettings s;
    std::istringstream words(optionString);
    for (std::string word; words >> word;) {
        if (word.rfind("chunk=", 0) == 0) {
            const std::string value = word.substr(6);
            const bool digits = !value.empty() && value.size() <= 4 && value.find_first_not_of("0123456789") == std::string::npos;
            const std::uint64_t n = digits ? std::stoull(value) : 0;
            if (n < 1 || n > 1024) throw std::runtime_error("option " + word + ": the chunk edge must be a whole number from 1 to 1024");
            s.chunk = n;
        } else if (word.rfind("compression=", 0) == 0) {
            const std::string value = word.substr(12);
            if (value == "none") s.compressor = ZarrCompressor{"", "", 0, 0, 0};
            else if (value == "zlib" || value == "gzip") s.compressor = ZarrCompressor{value, "", 6, 0, 0};
            else if (value == "blosc-lz4" || value == "blosc-lz4hc" || value == "blosc-zstd" || value == "blosc-zlib" ||
                     value == "blosc-blosclz")
                s.compressor = ZarrCompressor{"blosc", value.substr(6), 5, 1, 0};
            else
                throw std::runtime_error("option " + word +
                                         ": compression must be blosc-lz4, blosc-lz4hc, blosc-zstd, blosc-zlib, blosc-blosclz, zlib, gzip or none");
        }
    }
    return s;
}

void writeOmeZarr(const Volume& volume, const std::string& pathText, const WriteSettings& settings, const osgDB::Options* options)
{
    std::string name = pathText;
    while (name.size() > 1 && name.back() == '/') name.pop_back();
    if (volume.totalVoxelCount() == 0) throw std::runtime_error(name + ": the volume is empty");
    const fs::path path(name);
    std::error_code ec;
    if (fs::exists(path, ec) && !isReplaceableFolder(path))
        throw std::runtime_error(name + ": exists and is not a zarr folder; not replacing it");
    const fs::path tmp = name + ".tmp-" + std::to_string(::getpid());
    fs::remove_all(tmp, ec);
    try {
        PyramidWriter(volume, tmp, settings, options, name).write();
        if (fs::exists(path, ec)) {
            // Replace the old folder only now: move it aside, move the new one in, drop the old.
            const fs::path old = name + ".old-" + std::to_string(::getpid());
            fs::remove_all(old, ec);
            fs::rename(path, old);
            fs::rename(tmp, path);
            fs::remove_all(old, ec);
        } else {
            fs::rename(tmp, path);
        }
    } catch (const fs::filesystem_error& e) {
        fs::remove_all(tmp, ec);
        throw std::runtime_error(name + ": " + e.what());
    } catch (...) {
        fs::remove_all(tmp, ec);
        throw;
    }
}

}  // namespace volren::omezarr
