#include "QvisDescription.h"

#include "HeaderText.h"

#include <volume_model/ParseNumber.h>

#include <sstream>
#include <stdexcept>

namespace volren::rawvolume {

PayloadLayout describeQvisFile(const std::string& path)
{
    const std::string text = readFileHead(path, 1 << 16);
    const auto bad = [&](const std::string& why) { return std::runtime_error(path + ": " + why); };
    PayloadLayout layout;
    layout.name = path;
    std::string objectFile, format;
    bool haveResolution = false;
    std::stringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        const auto colon = line.find(':');
        if (trim(line).empty()) continue;
        if (colon == std::string::npos) throw bad("not a QVis .dat header (line '" + trim(line).substr(0, 40) + "' has no ':')");
        const std::string key = lowerCase(trim(line.substr(0, colon)));
        const std::string value = trim(line.substr(colon + 1));
        const std::vector<std::string> words = splitWords(value);
        if (key == "objectfilename") {
            objectFile = value;
        } else if (key == "resolution") {
            if (words.size() != 3) throw bad("Resolution '" + value + "' must be three integers");
            for (int a = 0; a < 3; ++a) {
                long long v = 0;
                if (!parseInteger(words[a], v) || v > 0x7fffffff || v < -0x7fffffff) throw bad("Resolution '" + value + "' must be three integers");
                layout.dims[a] = int(v);
            }
            haveResolution = true;
        } else if (key == "slicethickness") {
            if (words.size() != 3) throw bad("SliceThickness '" + value + "' must be three numbers");
            for (int a = 0; a < 3; ++a)
                if (!parseFiniteNumber(words[a], layout.spacing[a])) throw bad("SliceThickness '" + value + "' must be three finite numbers");
        } else if (key == "format") {
            format = value;
        } else if (key == "objectmodel") {
            const std::string m = lowerCase(value);
            if (m == "i") layout.channels = 1;
            else if (m == "rgb") layout.channels = 3;
            else if (m == "rgba") layout.channels = 4;
            else throw bad("unsupported ObjectModel '" + value + "' (I, RGB or RGBA)");
        }
    }
    if (objectFile.empty()) throw bad("not a QVis .dat header (no ObjectFileName)");
    if (!haveResolution) throw bad("QVis header has no Resolution");
    if (format == "UCHAR") layout.type = FileVoxelType::UInt8;
    else if (format == "CHAR") layout.type = FileVoxelType::Int8;
    else if (format == "USHORT") layout.type = FileVoxelType::UInt16;
    else if (format == "SHORT") layout.type = FileVoxelType::Int16;
    else if (format == "FLOAT") layout.type = FileVoxelType::Float32;
    else throw bad("unsupported Format '" + format + "' (UCHAR, CHAR, USHORT, SHORT or FLOAT)");
    PayloadPart part;
    part.path = resolveDataFile(path, objectFile);
    layout.parts.push_back(part);
    return layout;
}

}  // namespace volren::rawvolume
