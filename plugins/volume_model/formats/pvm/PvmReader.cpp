#include "PvmReader.h"
#include "DdsDecoder.h"

#include <volume_model/ParseNumber.h>

#include <osg/Notify>

#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace volren::pvm {

namespace {

/// Largest decoded DDS stream accepted (64 GiB).
constexpr std::uint64_t maxDecodedBytes = std::uint64_t(1) << 36;

/// Longest header line accepted; a PVM header is a few short text lines.
constexpr std::size_t maxLineLength = 4096;

/// Reads the header text line by line from the start of the file.
class HeaderCursor
{
public:
    HeaderCursor(const std::vector<std::uint8_t>& bytes, const std::string& name) : _bytes(bytes), _name(name) {}

    /// The next line without its '\n'; throws when the file ends first.
    std::string line(const char* what)
    {
        std::size_t end = _pos;
        while (end < _bytes.size() && _bytes[end] != '\n') {
            if (end - _pos > maxLineLength) throw std::runtime_error(_name + ": PVM header line too long (" + what + ")");
            ++end;
        }
        if (end >= _bytes.size()) throw std::runtime_error(_name + ": truncated: PVM header ends before " + what);
        std::string text(reinterpret_cast<const char*>(_bytes.data() + _pos), end - _pos);
        _pos = end + 1;
        if (!text.empty() && text.back() == '\r') text.pop_back();
        return text;
    }

    /// The next line as exactly `count` numbers.
    std::vector<double> numbers(std::size_t count, const char* what)
    {
        const std::string text = line(what);
        std::istringstream words(text);
        std::vector<double> values;
        for (std::string word; words >> word;) {
            double v = 0.0;
            if (!parseFiniteNumber(word, v))
                throw std::runtime_error(_name + ": bad PVM " + what + " '" + text + "' (not a number: " + word + ")");
            values.push_back(v);
        }
        if (values.size() != count)
            throw std::runtime_error(_name + ": bad PVM " + what + " '" + text + "' (expected " + std::to_string(count) +
                                     " numbers)");
        return values;
    }

    bool peek(char c) const { return _pos < _bytes.size() && _bytes[_pos] == c; }
    std::size_t position() const { return _pos; }

private:
    const std::vector<std::uint8_t>& _bytes;
    const std::string& _name;
    std::size_t _pos = 0;
};

int dimension(double v, const std::string& name, const char* axis)
{
    if (!(v >= -2147483648.0 && v <= 2147483647.0) || v != std::floor(v))
        throw std::runtime_error(name + ": PVM " + axis + " size " + std::to_string(v) + " is not an integer in range");
    return int(v);
}

/// Null-terminated strings that PVM3 appends after the voxels (description, courtesy, ...).
void logTrailingStrings(const std::vector<std::uint8_t>& bytes, std::size_t from, const std::string& name)
{
    static const char* const labels[] = {"description", "courtesy", "parameters", "comment"};
    std::size_t pos = from;
    for (const char* label : labels) {
        if (pos >= bytes.size()) break;
        std::size_t end = pos;
        while (end < bytes.size() && bytes[end] != 0) ++end;
        if (end > pos)
            OSG_INFO << name << ": PVM3 " << label << ": "
                     << std::string(reinterpret_cast<const char*>(bytes.data() + pos), end - pos) << std::endl;
        pos = end + 1;
    }
}

}  // namespace

osg::ref_ptr<Volume> readPvm(const std::vector<std::uint8_t>& bytes, const std::string& name)
{
    if (isDds(bytes)) {  // compressed: the DDS stream holds a whole uncompressed PVM file
        const std::vector<std::uint8_t> plain = decodeDds(bytes, name, maxDecodedBytes);
        if (isDds(plain)) throw std::runtime_error(name + ": DDS stream inside a DDS stream");
        return readPvm(plain, name);
    }

    HeaderCursor header(bytes, name);
    const std::string magic = header.line("the magic line");
    int version = 0;
    if (magic == "PVM") version = 1;
    else if (magic == "PVM2") version = 2;
    else if (magic == "PVM3") version = 3;
    else throw std::runtime_error(name + ": not a PVM file (the first line must be PVM, PVM2 or PVM3)");

    if (version == 1)
        while (header.peek('#')) header.line("the dimensions");  // comment lines
    const std::vector<double> d = header.numbers(3, "dimensions");
    const osg::Vec3i dims(dimension(d[0], name, "x"), dimension(d[1], name, "y"), dimension(d[2], name, "z"));
    osg::Vec3d spacing(1, 1, 1);
    if (version >= 2) {
        const std::vector<double> s = header.numbers(3, "voxel spacing");
        for (int a = 0; a < 3; ++a) {
            if (!(s[a] > 0.0))
                throw std::runtime_error(name + ": PVM voxel spacing " + std::to_string(s[a]) + " is not positive");
            spacing[a] = s[a];
        }
    }
    const double components = header.numbers(1, "bytes per voxel")[0];
    if (components != 1.0 && components != 2.0)
        throw std::runtime_error(name + ": unsupported PVM voxel size " + std::to_string(components) +
                                 " bytes (only 1 and 2 bytes per voxel are read)");
    const std::size_t width = std::size_t(components);

    std::uint64_t count = 0;
    try {
        count = Volume::checkedVoxelCount(dims);
    } catch (const std::exception& e) {
        throw std::runtime_error(name + ": " + e.what());
    }
    const std::uint64_t needed = count * width;
    const std::uint64_t available = bytes.size() - header.position();
    if (available < needed)
        throw std::runtime_error(name + ": truncated: voxel data needs " + std::to_string(needed) + " bytes, file has " +
                                 std::to_string(available));

    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(width == 1 ? VoxelType::UInt8 : VoxelType::UInt16, dims);
    const std::uint8_t* src = bytes.data() + header.position();
    if (width == 1) {
        std::memcpy(volume->data(), src, std::size_t(count));
    } else {
        auto* dst = volume->data();
        for (std::size_t i = 0; i < std::size_t(count); ++i) {
            const std::uint16_t v = std::uint16_t((src[2 * i] << 8) | src[2 * i + 1]);  // big-endian in the file
            std::memcpy(dst + 2 * i, &v, 2);
        }
    }
    const std::uint64_t extra = available - needed;
    if (version == 3) logTrailingStrings(bytes, std::size_t(header.position() + needed), name);
    else if (extra > 0) OSG_WARN << name << ": " << extra << " bytes after the PVM voxel data are ignored" << std::endl;

    volume->setSpacing(spacing);
    volume->sourceFile = name;
    volume->setName(name);
    return volume;
}

}  // namespace volren::pvm
