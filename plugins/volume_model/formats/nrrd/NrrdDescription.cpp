#include "NrrdDescription.h"

#include <HeaderText.h>

#include <volume_model/ParseNumber.h>

#include <osg/Notify>

#include <cmath>
#include <map>
#include <stdexcept>

namespace volren::nrrd {

using namespace rawvolume;

namespace {

constexpr std::size_t maxHeaderBytes = std::size_t(1) << 22;

bool parseNrrdType(const std::string& name, FileVoxelType& type)
{
    static const struct { const char* name; FileVoxelType type; } names[] = {
        {"signed char", FileVoxelType::Int8},     {"int8", FileVoxelType::Int8},        {"int8_t", FileVoxelType::Int8},
        {"uchar", FileVoxelType::UInt8},          {"unsigned char", FileVoxelType::UInt8}, {"uint8", FileVoxelType::UInt8},
        {"uint8_t", FileVoxelType::UInt8},        {"short", FileVoxelType::Int16},      {"short int", FileVoxelType::Int16},
        {"signed short", FileVoxelType::Int16},   {"signed short int", FileVoxelType::Int16}, {"int16", FileVoxelType::Int16},
        {"int16_t", FileVoxelType::Int16},        {"ushort", FileVoxelType::UInt16},    {"unsigned short", FileVoxelType::UInt16},
        {"unsigned short int", FileVoxelType::UInt16}, {"uint16", FileVoxelType::UInt16}, {"uint16_t", FileVoxelType::UInt16},
        {"int", FileVoxelType::Int32},            {"signed int", FileVoxelType::Int32}, {"int32", FileVoxelType::Int32},
        {"int32_t", FileVoxelType::Int32},        {"uint", FileVoxelType::UInt32},      {"unsigned int", FileVoxelType::UInt32},
        {"uint32", FileVoxelType::UInt32},        {"uint32_t", FileVoxelType::UInt32},  {"float", FileVoxelType::Float32},
        {"double", FileVoxelType::Float64},
    };
    for (const auto& n : names)
        if (name == n.name) {
            type = n.type;
            return true;
        }
    return false;
}

/// Lengths of the vectors in "(1,0,0) (0,1,0) none ..."; NaN for "none".
std::vector<double> directionLengths(const std::string& value, const std::string& path)
{
    std::vector<double> lengths;
    std::size_t i = 0;
    while (i < value.size()) {
        if (std::isspace(static_cast<unsigned char>(value[i]))) {
            ++i;
        } else if (value.compare(i, 4, "none") == 0) {
            lengths.push_back(std::nan(""));
            i += 4;
        } else if (value[i] == '(') {
            const std::size_t close = value.find(')', i);
            if (close == std::string::npos) throw std::runtime_error(path + ": space directions: missing ')'");
            std::string inner = value.substr(i + 1, close - i - 1);
            double sum = 0.0;
            std::size_t start = 0;
            while (true) {
                const std::size_t comma = inner.find(',', start);
                double c = 0.0;
                const std::string text = trim(inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
                if (!parseFiniteNumber(text, c))
                    throw std::runtime_error(path + ": space directions: '" + text + "' is not a finite number");
                sum += c * c;
                if (comma == std::string::npos) break;
                start = comma + 1;
            }
            lengths.push_back(std::sqrt(sum));
            i = close + 1;
        } else {
            throw std::runtime_error(path + ": space directions: expected '(x,y,z)' or 'none' in '" + value + "'");
        }
    }
    return lengths;
}

}  // namespace

PayloadLayout describeNrrdFile(const std::string& path)
{
    const std::string head = readFileHead(path, maxHeaderBytes);
    const auto bad = [&](const std::string& why) { return std::runtime_error(path + ": " + why); };
    if (head.compare(0, 7, "NRRD000") != 0 || head.size() < 8 || head[7] < '1' || head[7] > '5')
        throw bad("not a NRRD file (it does not start with NRRD0001..NRRD0005)");

    // Fields up to the blank line that ends the header (or the end of a detached header).
    std::map<std::string, std::string> fields;
    std::map<std::string, std::string> keyValues;
    std::vector<std::string> listedFiles;
    bool listFollows = false, ended = false;
    std::size_t pos = head.find('\n');
    if (pos == std::string::npos) throw bad("truncated: header has no end");
    ++pos;
    std::size_t dataStart = head.size();
    while (pos < head.size()) {
        std::size_t eol = head.find('\n', pos);
        const bool lastLine = eol == std::string::npos;
        if (lastLine) eol = head.size();
        std::string line = head.substr(pos, eol - pos);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        pos = lastLine ? head.size() : eol + 1;
        if (line.empty()) {
            ended = true;
            dataStart = pos;
            break;
        }
        if (listFollows) {
            listedFiles.push_back(trim(line));
            continue;
        }
        if (line[0] == '#') continue;
        if (const auto kv = line.find(":="); kv != std::string::npos) {
            keyValues[line.substr(0, kv)] = line.substr(kv + 2);
            continue;
        }
        const auto colon = line.find(": ");
        if (colon == std::string::npos) throw bad("header line '" + line.substr(0, 60) + "' is not 'field: value'");
        const std::string field = lowerCase(trim(line.substr(0, colon)));
        const std::string value = trim(line.substr(colon + 2));
        if (fields.count(field)) throw bad("field '" + field + "' appears twice");
        fields[field == "datafile" ? "data file" : field == "byteskip" ? "byte skip" : field == "lineskip" ? "line skip" : field] = value;
        if ((field == "data file" || field == "datafile") && lowerCase(splitWords(value).empty() ? "" : splitWords(value)[0]) == "list")
            listFollows = true;
    }
    const bool detached = fields.count("data file") > 0;
    if (!ended && !detached) {
        if (head.size() >= maxHeaderBytes) throw bad("no blank line ends the header within " + std::to_string(maxHeaderBytes) + " bytes");
        throw bad("truncated: the header has no data file and no blank line before attached data");
    }
    for (const char* required : {"type", "dimension", "sizes", "encoding"})
        if (!fields.count(required)) throw bad(std::string("required field '") + required + "' is missing");

    PayloadLayout layout;
    layout.name = path;
    if (!parseNrrdType(fields["type"], layout.type)) {
        const std::string t = fields["type"];
        throw bad("unsupported type '" + t + "' (volren reads signed/unsigned char, short, int as float32, float, and double as float32)");
    }

    long long dimension = 0;
    if (!parseInteger(fields["dimension"], dimension) || (dimension != 3 && dimension != 4))
        throw bad("dimension '" + fields["dimension"] + "' is not supported (3, or 4 with a leading channel axis)");
    const std::vector<std::string> sizeWords = splitWords(fields["sizes"]);
    if (sizeWords.size() != std::size_t(dimension))
        throw bad("sizes '" + fields["sizes"] + "' must list " + std::to_string(dimension) + " sizes");
    std::vector<long long> sizes;
    for (const std::string& w : sizeWords) {
        long long v = 0;
        if (!parseInteger(w, v)) throw bad("sizes: '" + w + "' is not an integer");
        if (v > 0x7fffffff || v < -0x7fffffff) throw bad("sizes: " + w + " is too large");
        sizes.push_back(v);
    }
    const int first = dimension == 4 ? 1 : 0;  // the leading channel axis of a 4D file
    if (dimension == 4) {
        const std::vector<std::string> kinds = splitWords(fields["kinds"]);
        const std::string kind = kinds.empty() ? "" : lowerCase(kinds[0]);
        if (kind == "domain" || kind == "space" || kind == "time")
            throw bad("4D NRRD with a '" + kind + "' first axis is not supported (the first axis must hold channels: RGB-color, vector, list, ...)");
        if (sizes[0] < 1 || sizes[0] > 1024) throw bad("channel axis size " + std::to_string(sizes[0]) + " must be 1..1024");
        layout.channels = int(sizes[0]);
    }
    for (int a = 0; a < 3; ++a) layout.dims[a] = int(sizes[std::size_t(first + a)]);

    if (fields.count("spacings")) {
        const std::vector<std::string> words = splitWords(fields["spacings"]);
        if (words.size() != std::size_t(dimension)) throw bad("spacings '" + fields["spacings"] + "' must list " + std::to_string(dimension) + " values");
        for (int a = 0; a < 3; ++a) {
            const std::string& w = words[std::size_t(first + a)];
            if (!parseFiniteNumber(w, layout.spacing[a]) || !(layout.spacing[a] > 0.0))
                throw bad("spacings: '" + w + "' is not a positive finite spacing");
        }
    } else if (fields.count("space directions")) {
        const std::vector<double> lengths = directionLengths(fields["space directions"], path);
        if (lengths.size() != std::size_t(dimension))
            throw bad("space directions must list " + std::to_string(dimension) + " vectors (or none)");
        for (int a = 0; a < 3; ++a) {
            layout.spacing[a] = lengths[std::size_t(first + a)];
            if (!(layout.spacing[a] > 0.0) || !std::isfinite(layout.spacing[a]))
                throw bad("space directions: axis " + std::to_string(first + a) + " has no positive finite length");
        }
    } else {
        OSG_NOTICE << path << ": no spacings or space directions; using spacing 1" << std::endl;
    }
    if (fields.count("space origin"))
        OSG_INFO << path << ": space origin is ignored (the VolumeNode places the volume)" << std::endl;

    if (fileVoxelSize(layout.type) > 1) {
        if (!fields.count("endian")) throw bad("required field 'endian' is missing (the type has more than one byte)");
        const std::string e = lowerCase(fields["endian"]);
        if (e != "little" && e != "big") throw bad("endian '" + fields["endian"] + "' must be little or big");
        layout.bigEndian = e == "big";
    }

    PayloadPart part;
    const std::string encoding = lowerCase(fields["encoding"]);
    if (encoding == "gzip" || encoding == "gz") part.compression = Compression::Zlib;
    else if (encoding != "raw")
        throw bad("unsupported encoding '" + fields["encoding"] + "' (volren reads raw and gzip)");
    if (fields.count("line skip")) {
        long long n = 0;
        if (!parseInteger(fields["line skip"], n) || n < 0) throw bad("line skip '" + fields["line skip"] + "' must be >= 0");
        part.lineSkip = std::uint64_t(n);
    }
    if (fields.count("byte skip")) {
        long long n = 0;
        if (!parseInteger(fields["byte skip"], n) || n < -1) throw bad("byte skip '" + fields["byte skip"] + "' must be >= -1");
        if (n != 0 && part.compression != Compression::None) throw bad("byte skip with gzip encoding is not supported");
        part.byteSkip = n;
    }
    if (const auto kv = keyValues.find("volren_rescale"); kv != keyValues.end()) {
        const std::vector<std::string> words = splitWords(kv->second);
        if (words.size() != 2 || !parseFiniteNumber(words[0], layout.slope) || !parseFiniteNumber(words[1], layout.intercept))
            throw bad("volren_rescale '" + kv->second + "' must be 'slope intercept'");
    }

    std::vector<std::string> files;
    if (!detached) {
        part.path = path;
        part.offset = dataStart;
        layout.parts.push_back(part);
        return layout;
    }
    const std::string dataFile = fields["data file"];
    const std::vector<std::string> words = splitWords(dataFile);
    long long lo = 0, hi = 0, step = 0;
    if (listFollows) {
        files = listedFiles;
        if (files.empty()) throw bad("data file: LIST names no files");
    } else if (words.size() >= 4 && parseInteger(words[1], lo) && parseInteger(words[2], hi) && parseInteger(words[3], step)) {
        files = expandFilePattern(words[0], lo, hi, step, path);
    } else {
        if (dataFile.empty()) throw bad("data file names no file");
        files.push_back(dataFile);
    }
    for (const std::string& f : files) {
        part.path = resolveDataFile(path, f);
        layout.parts.push_back(part);
    }
    return layout;
}

}  // namespace volren::nrrd
