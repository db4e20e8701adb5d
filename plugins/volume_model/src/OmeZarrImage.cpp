#include <volume_model/OmeZarrImage.h>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace volren {

namespace fs = std::filesystem;

namespace {

bool isFile(const std::string& path)
{
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

std::string readText(const std::string& file)
{
    if (!isFile(file)) throw std::runtime_error(file + ": no such file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file + ": cannot open: " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Whether `.zattrs` text names a bioformats2raw layout without multiscales of its own.
bool isBioformats2rawLayout(const std::string& text)
{
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    return j.is_object() && j.contains("bioformats2raw.layout") && !j.contains("multiscales");
}

/// Metadata for a bare array of `dimensions` dimensions: [t] [c] z y x, or y x.
OmeZarrAttributes bareArrayAttributes(std::size_t dimensions, const std::string& file)
{
    static const char* const names[] = {"t", "c", "z", "y", "x"};
    static const char* const types[] = {"time", "channel", "space", "space", "space"};
    if (dimensions < 2 || dimensions > 5)
        throw std::runtime_error(file + ": a bare zarr array of " + std::to_string(dimensions) +
                                 " dimensions is not an image (volren reads 2 to 5: [t] [c] z y x)");
    OmeZarrAttributes a;
    for (std::size_t i = 5 - dimensions; i < 5; ++i) a.axes.push_back({names[i], types[i], ""});
    a.levels.push_back({".", std::vector<double>(dimensions, 1.0), std::vector<double>(dimensions, 0.0)});
    return a;
}

std::string sizeText(const std::vector<std::uint64_t>& shape)
{
    std::string text;
    for (std::size_t i = 0; i < shape.size(); ++i) text += (i ? "x" : "") + std::to_string(shape[i]);
    return text;
}

}  // namespace

OmeZarrImage::OmeZarrImage(const std::string& path) : _path(path)
{
    while (_path.size() > 1 && _path.back() == '/') _path.pop_back();
    std::error_code ec;
    if (!fs::exists(_path, ec)) throw std::runtime_error(_path + ": no such file or folder");
    if (!fs::is_directory(_path, ec)) throw std::runtime_error(_path + ": not a folder (an OME-Zarr image is a folder)");
    if (isFile(_path + "/zarr.json"))
        throw std::runtime_error(_path + "/zarr.json: zarr v3 (OME-Zarr 0.5) is not supported; volren reads OME-Zarr 0.4 (zarr v2)");
    std::string attributesFile = _path + "/.zattrs";
    if (isFile(attributesFile) && isBioformats2rawLayout(readText(attributesFile))) {
        _path += "/0";  // bioformats2raw: the images are numbered subgroups; volren reads the first
        attributesFile = _path + "/.zattrs";
    }
    const bool bareArray = isFile(_path + "/.zarray");
    if (isFile(attributesFile) && !bareArray) {
        _attributes = parseOmeZarrAttributes(readText(attributesFile), attributesFile);
    } else if (bareArray) {
        auto array = std::make_unique<ZarrArray>(_path);
        _attributes = bareArrayAttributes(array->dimensions(), _path + "/.zarray");
        _levels.push_back(std::move(array));
    } else if (isFile(_path + "/.zgroup")) {
        throw std::runtime_error(attributesFile + ": no such file (a zarr group without OME-Zarr metadata)");
    } else {
        throw std::runtime_error(_path + ": neither an OME-Zarr image nor a zarr array (no .zattrs, .zgroup or .zarray)");
    }
    if (_levels.empty())
        for (const OmeZarrLevel& level : _attributes.levels) _levels.push_back(std::make_unique<ZarrArray>(_path + "/" + level.path));

    _time = _attributes.axisOfType("time");
    _channel = _attributes.channelAxis();
    std::vector<int> space;
    for (std::size_t i = 0; i < _attributes.axes.size(); ++i)
        if (_attributes.axes[i].type == "space") space.push_back(int(i));
    // Space axes by name when they are x, y (and z); otherwise by position: the last is x.
    bool named = true;
    for (int i : space) named = named && (_attributes.axes[i].name == "x" || _attributes.axes[i].name == "y" || _attributes.axes[i].name == "z");
    for (std::size_t k = 0; k < space.size(); ++k) {
        const int axis = space[k];
        const std::size_t xyz = named ? std::size_t(_attributes.axes[axis].name[0] == 'x' ? 0 : _attributes.axes[axis].name[0] == 'y' ? 1 : 2)
                                      : space.size() - 1 - k;
        _space[xyz] = axis;
    }
    if (_space[0] < 0 || _space[1] < 0) throw std::runtime_error(attributesFile + ": the space axes are not x and y (and z)");
    checkLevels();
}

void OmeZarrImage::checkLevels() const
{
    const std::size_t n = _attributes.axes.size();
    const ZarrArrayMetadata& first = _levels.front()->metadata();
    for (std::size_t i = 0; i < _levels.size(); ++i) {
        const ZarrArrayMetadata& m = _levels[i]->metadata();
        const std::string file = _levels[i]->path() + "/.zarray";
        if (m.shape.size() != n)
            throw std::runtime_error(file + ": level " + std::to_string(i) + " has " + std::to_string(m.shape.size()) +
                                     " dimensions but the image has " + std::to_string(n) + " axes");
        if (m.dtype.kind != first.dtype.kind || m.dtype.size != first.dtype.size)
            throw std::runtime_error(file + ": level " + std::to_string(i) + " has dtype " + m.dtype.str() + " but level 0 has " +
                                     first.dtype.str() + " (the levels disagree)");
        if (i == 0) continue;
        const ZarrArrayMetadata& previous = _levels[i - 1]->metadata();
        for (std::size_t d = 0; d < n; ++d) {
            const bool space = _attributes.axes[d].type == "space";
            if (space ? m.shape[d] > previous.shape[d] : m.shape[d] != first.shape[d])
                throw std::runtime_error(file + ": level " + std::to_string(i) + " is " + sizeText(m.shape) + " but level " +
                                         std::to_string(space ? i - 1 : 0) + " is " + sizeText(space ? previous.shape : first.shape) +
                                         " (the levels disagree along axis \"" + _attributes.axes[d].name + "\": " +
                                         (space ? "a coarser level must not be larger" : "time points and channels must match") + ")");
        }
    }
}

const ZarrArray& OmeZarrImage::level(std::size_t i) const
{
    if (i >= _levels.size())
        throw std::out_of_range(_path + ": level " + std::to_string(i) + " does not exist (levels 0 to " + std::to_string(_levels.size() - 1) + ")");
    return *_levels[i];
}

std::uint64_t OmeZarrImage::frames() const
{
    return _time < 0 ? 1 : _levels.front()->metadata().shape[std::size_t(_time)];
}

std::uint64_t OmeZarrImage::channels() const
{
    return _channel < 0 ? 1 : _levels.front()->metadata().shape[std::size_t(_channel)];
}

std::array<std::uint64_t, 3> OmeZarrImage::size(std::size_t i) const
{
    const std::vector<std::uint64_t>& shape = level(i).metadata().shape;
    std::array<std::uint64_t, 3> s{1, 1, 1};
    for (std::size_t k = 0; k < 3; ++k)
        if (_space[k] >= 0) s[k] = shape[std::size_t(_space[k])];
    return s;
}

std::array<double, 3> OmeZarrImage::spacing(std::size_t i) const
{
    level(i);
    const std::vector<double>& scale = _attributes.levels[i].scale;
    std::array<double, 3> s{};
    for (std::size_t k = 0; k < 3; ++k) s[k] = scale[std::size_t(_space[_space[k] >= 0 ? k : 0])];
    return s;
}

std::array<double, 3> OmeZarrImage::origin(std::size_t i) const
{
    level(i);
    const std::vector<double>& t = _attributes.levels[i].translation;
    std::array<double, 3> o{};
    for (std::size_t k = 0; k < 3; ++k) o[k] = _space[k] >= 0 ? t[std::size_t(_space[k])] : 0.0;
    return o;
}

std::string OmeZarrImage::spaceUnit() const
{
    std::string unit;
    for (std::size_t k = 0; k < 3; ++k) {
        if (_space[k] < 0) continue;
        const std::string& u = _attributes.axes[std::size_t(_space[k])].unit;
        if (k > 0 && u != unit) return "";
        unit = u;
    }
    return unit;
}

std::string OmeZarrImage::timeUnit() const
{
    return _time < 0 ? std::string() : _attributes.axes[std::size_t(_time)].unit;
}

double OmeZarrImage::timeStep(std::size_t i) const
{
    level(i);
    return _time < 0 ? 1.0 : _attributes.levels[i].scale[std::size_t(_time)];
}

}  // namespace volren
