#include "MetaImageDescription.h"

#include <HeaderText.h>

#include <volume_model/ParseNumber.h>

#include <map>
#include <stdexcept>

namespace volren::metaimage {

using namespace rawvolume;

namespace {

constexpr std::size_t maxHeaderBytes = std::size_t(1) << 22;

bool parseBool(const std::string& value, bool& out)
{
    const std::string v = lowerCase(value);
    if (v == "true" || v == "1") out = true;
    else if (v == "false" || v == "0") out = false;
    else return false;
    return true;
}

bool parseElementType(std::string name, FileVoxelType& type)
{
    const std::string suffix = "_ARRAY";
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
        name.resize(name.size() - suffix.size());
    static const struct { const char* name; FileVoxelType type; } names[] = {
        {"MET_UCHAR", FileVoxelType::UInt8}, {"MET_CHAR", FileVoxelType::Int8},    {"MET_USHORT", FileVoxelType::UInt16},
        {"MET_SHORT", FileVoxelType::Int16}, {"MET_INT", FileVoxelType::Int32},    {"MET_UINT", FileVoxelType::UInt32},
        {"MET_FLOAT", FileVoxelType::Float32}, {"MET_DOUBLE", FileVoxelType::Float64},
    };
    for (const auto& n : names)
        if (name == n.name) {
            type = n.type;
            return true;
        }
    return false;
}

}  // namespace

PayloadLayout describeMetaImageFile(const std::string& path)
{
    const std::string head = readFileHead(path, maxHeaderBytes);
    const auto bad = [&](const std::string& why) { return std::runtime_error(path + ": " + why); };

    std::map<std::string, std::string> fields;
    std::vector<std::string> listedFiles;
    std::size_t pos = 0, dataStart = 0;
    bool haveDataFile = false;
    while (pos < head.size() && !haveDataFile) {
        std::size_t eol = head.find('\n', pos);
        const bool lastLine = eol == std::string::npos;
        if (lastLine) eol = head.size();
        std::string line = head.substr(pos, eol - pos);
        pos = lastLine ? head.size() : eol + 1;
        if (trim(line).empty()) continue;
        const auto eq = line.find('=');
        if (eq == std::string::npos) throw bad("not a MetaImage header (line '" + trim(line).substr(0, 60) + "' is not 'Key = Value')");
        const std::string key = lowerCase(trim(line.substr(0, eq)));
        fields[key] = trim(line.substr(eq + 1));
        if (key == "elementdatafile") {  // always the last header entry
            haveDataFile = true;
            dataStart = pos;
        }
    }
    if (!haveDataFile) throw bad("the header has no ElementDataFile entry");
    if (fields.count("objecttype") && lowerCase(fields["objecttype"]) != "image")
        throw bad("ObjectType '" + fields["objecttype"] + "' is not supported (only Image)");
    for (const char* required : {"ndims", "dimsize", "elementtype"})
        if (!fields.count(required)) throw bad(std::string("required entry '") + required + "' is missing");

    PayloadLayout layout;
    layout.name = path;
    long long ndims = 0;
    if (!parseInteger(fields["ndims"], ndims) || ndims < 3 || ndims > 4)
        throw bad("NDims '" + fields["ndims"] + "' is not supported (3, or 4 with time points)");
    const std::vector<std::string> sizes = splitWords(fields["dimsize"]);
    if (sizes.size() != std::size_t(ndims)) throw bad("DimSize '" + fields["dimsize"] + "' must list " + std::to_string(ndims) + " sizes");
    for (std::size_t a = 0; a < sizes.size(); ++a) {
        long long v = 0;
        if (!parseInteger(sizes[a], v)) throw bad("DimSize: '" + sizes[a] + "' is not an integer");
        if (v > 0x7fffffff || v < -0x7fffffff) throw bad("DimSize: " + sizes[a] + " is too large");
        if (a < 3) layout.dims[int(a)] = int(v);
        else if (v < 1 || v > 100000) throw bad("DimSize: " + sizes[a] + " time points is out of range");
        else layout.frames = int(v);
    }
    if (fields.count("elementnumberofchannels")) {
        long long c = 0;
        if (!parseInteger(fields["elementnumberofchannels"], c) || c < 1 || c > 1024)
            throw bad("ElementNumberOfChannels '" + fields["elementnumberofchannels"] + "' must be 1..1024");
        layout.channels = int(c);
    }
    const char* spacingKey = fields.count("elementspacing") ? "elementspacing" : fields.count("elementsize") ? "elementsize" : nullptr;
    if (spacingKey) {
        const std::vector<std::string> words = splitWords(fields[spacingKey]);
        if (words.size() < 3) throw bad(std::string(spacingKey) + " '" + fields[spacingKey] + "' must list a spacing per axis");
        for (int a = 0; a < 3; ++a)
            if (!parseFiniteNumber(words[std::size_t(a)], layout.spacing[a]) || !(layout.spacing[a] > 0.0))
                throw bad("ElementSpacing: '" + words[std::size_t(a)] + "' is not a positive finite spacing");
    }
    if (!parseElementType(fields["elementtype"], layout.type))
        throw bad("ElementType '" + fields["elementtype"] +
                  "' is not supported (MET_UCHAR, MET_CHAR, MET_USHORT, MET_SHORT, MET_FLOAT; MET_INT/MET_UINT as exact float32, MET_DOUBLE as float32)");
    for (const char* key : {"binarydatabyteordermsb", "elementbyteordermsb"})
        if (fields.count(key) && !parseBool(fields[key], layout.bigEndian))
            throw bad(std::string(key) + " '" + fields[key] + "' must be True or False");
    bool binary = true;
    if (fields.count("binarydata") && (!parseBool(fields["binarydata"], binary) || !binary))
        throw bad("BinaryData = " + fields["binarydata"] + ": text (ASCII) voxel data is not supported");

    PayloadPart part;
    bool compressed = false;
    if (fields.count("compresseddata") && !parseBool(fields["compresseddata"], compressed))
        throw bad("CompressedData '" + fields["compresseddata"] + "' must be True or False");
    if (compressed) {
        part.compression = Compression::Zlib;
        if (fields.count("compresseddatasize")) {
            long long n = 0;
            if (!parseInteger(fields["compresseddatasize"], n) || n <= 0)
                throw bad("CompressedDataSize '" + fields["compresseddatasize"] + "' must be a positive byte count");
            part.compressedSize = std::uint64_t(n);
        }
    }
    if (fields.count("headersize")) {
        long long n = 0;
        if (!parseInteger(fields["headersize"], n) || n < -1) throw bad("HeaderSize '" + fields["headersize"] + "' must be >= -1");
        if (n != 0 && compressed) throw bad("HeaderSize with compressed data is not supported");
        part.byteSkip = n;
    }

    const std::string dataFile = fields["elementdatafile"];
    const std::vector<std::string> words = splitWords(dataFile);
    std::vector<std::string> files;
    long long lo = 0, hi = 0, step = 0;
    if (dataFile == "LOCAL") {
        part.path = path;
        part.offset = dataStart;
        layout.parts.push_back(part);
        return layout;
    }
    if (!words.empty() && words[0] == "LIST") {
        std::size_t p = dataStart;
        while (p < head.size()) {
            std::size_t eol = head.find('\n', p);
            if (eol == std::string::npos) eol = head.size();
            const std::string name = trim(head.substr(p, eol - p));
            if (!name.empty()) files.push_back(name);
            p = eol + 1;
        }
        if (files.empty()) throw bad("ElementDataFile = LIST names no files");
    } else if (words.size() >= 4 && parseInteger(words[1], lo) && parseInteger(words[2], hi) && parseInteger(words[3], step)) {
        files = expandFilePattern(words[0], lo, hi, step, path);
    } else {
        if (dataFile.empty()) throw bad("ElementDataFile names no file");
        files.push_back(dataFile);
    }
    if (files.size() > 1 && part.compressedSize) throw bad("CompressedDataSize with several data files is not supported");
    for (const std::string& f : files) {
        part.path = resolveDataFile(path, f);
        layout.parts.push_back(part);
    }
    return layout;
}

}  // namespace volren::metaimage
