#include "RawDescription.h"

#include "HeaderText.h"

#include <volume_model/ParseNumber.h>

#include <osgDB/FileUtils>

#include <map>
#include <sstream>
#include <stdexcept>

namespace volren::rawvolume {

namespace {

/// Splits "a,b,c" into three parts; false unless there are exactly three.
bool splitTriple(const std::string& text, std::string out[3])
{
    std::stringstream in(text);
    int n = 0;
    std::string part;
    while (std::getline(in, part, ',')) {
        if (n == 3) return false;
        out[n++] = part;
    }
    return n == 3;
}

void collectWords(const std::string& text, bool strict, const std::string& where, std::map<std::string, std::string>& keys)
{
    static const char* const known[] = {"dims", "type", "endian", "skip", "spacing", "channels", "encoding"};
    std::stringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        for (const std::string& word : splitWords(line)) {
            const auto eq = word.find('=');
            const std::string key = lowerCase(word.substr(0, eq));
            bool isKnown = false;
            for (const char* k : known) isKnown = isKnown || key == k;
            if (eq == std::string::npos || !isKnown) {
                if (strict) throw std::runtime_error(where + ": unknown entry '" + word + "' (expected dims=, type=, endian=, skip=, spacing=, channels=, encoding=)");
                continue;
            }
            keys[key] = word.substr(eq + 1);
        }
    }
}

}  // namespace

PayloadLayout describeRawFile(const std::string& path, const std::string& optionString)
{
    std::map<std::string, std::string> keys;
    const std::string sidecar = path + ".txt";
    if (osgDB::fileExists(sidecar)) collectWords(readFileHead(sidecar, 1 << 16), true, sidecar, keys);
    collectWords(optionString, false, path, keys);

    PayloadLayout layout;
    layout.name = path;
    const auto bad = [&](const std::string& why) { return std::runtime_error(path + ": " + why); };
    if (!keys.count("dims") || !keys.count("type"))
        throw bad("a .raw file needs dims=X,Y,Z and type=... (in the reader options or in " + sidecar + ")");

    std::string parts[3];
    if (!splitTriple(keys["dims"], parts)) throw bad("dims '" + keys["dims"] + "' must be X,Y,Z");
    for (int a = 0; a < 3; ++a) {
        long long v = 0;
        if (!parseInteger(parts[a], v)) throw bad("dims '" + keys["dims"] + "' must be three integers");
        if (v > 0x7fffffff || v < -0x7fffffff) throw bad("dims '" + keys["dims"] + "': " + parts[a] + " is too large");
        layout.dims[a] = int(v);
    }
    if (!parseFileVoxelType(lowerCase(keys["type"]), layout.type))
        throw bad("unknown voxel type '" + keys["type"] + "' (uint8, int8, uint16, int16, int32, uint32, float32, float64)");
    if (keys.count("endian")) {
        const std::string e = lowerCase(keys["endian"]);
        if (e != "little" && e != "big") throw bad("endian '" + keys["endian"] + "' must be little or big");
        layout.bigEndian = e == "big";
    }
    if (keys.count("spacing")) {
        if (!splitTriple(keys["spacing"], parts)) throw bad("spacing '" + keys["spacing"] + "' must be X,Y,Z");
        for (int a = 0; a < 3; ++a)
            if (!parseFiniteNumber(parts[a], layout.spacing[a]))
                throw bad("spacing '" + keys["spacing"] + "' must be three finite numbers");
    }
    if (keys.count("channels")) {
        long long c = 0;
        if (!parseInteger(keys["channels"], c) || c < 1 || c > 1024) throw bad("channels '" + keys["channels"] + "' must be 1..1024");
        layout.channels = int(c);
    }
    PayloadPart part;
    part.path = path;
    if (keys.count("skip")) {
        long long s = 0;
        if (!parseInteger(keys["skip"], s) || s < -1) throw bad("skip '" + keys["skip"] + "' must be a byte count (or -1: data at the end)");
        part.byteSkip = s;
    }
    if (keys.count("encoding")) {
        const std::string e = lowerCase(keys["encoding"]);
        if (e == "gzip" || e == "gz") part.compression = Compression::Zlib;
        else if (e != "raw") throw bad("unknown encoding '" + keys["encoding"] + "' (raw or gzip)");
    }
    layout.parts.push_back(part);
    return layout;
}

}  // namespace volren::rawvolume
