#include "DicomStructure.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace volren::dicom {

namespace {

constexpr std::uint32_t undefinedLength = 0xFFFFFFFFu;
constexpr std::uint16_t itemGroup = 0xFFFE;
constexpr std::uint16_t item = 0xE000, itemEnd = 0xE00D, sequenceEnd = 0xE0DD;

std::string hex4(std::uint16_t value)
{
    char text[5];
    std::snprintf(text, sizeof(text), "%04x", value);
    return text;
}

std::string tagName(std::uint16_t group, std::uint16_t element, std::uint64_t offset)
{
    std::ostringstream s;
    s << "element (" << std::hex;
    s.width(4), s.fill('0'), s << group;
    s << ',';
    s.width(4), s.fill('0'), s << element;
    s << std::dec << ") at byte " << offset;
    return s.str();
}

/// Reads element headers with seeks: the values (pixel data) are skipped, not read.
class Walker
{
public:
    Walker(std::ifstream& in, std::uint64_t size) : _in(in), _size(size) {}

    bool bigEndian = false;
    bool pixelData = false;  ///< (7FE0,0010) met at the top level
    std::string problem;

    /// The data elements from `pos` up to `end`, or (undefined length) up to the delimiter `stopAt`.
    std::uint64_t dataSet(std::uint64_t pos, std::uint64_t end, bool explicitVr, std::uint16_t stopAt, int depth)
    {
        std::uint32_t previous = 0;  // elements come in ascending tag order (PS3.5 7.1)
        bool first = true;
        while (problem.empty() && pos < end) {
            std::uint16_t group = 0, element = 0;
            if (!tag(pos, group, element)) return fail("truncated tag at byte " + std::to_string(pos));
            if (group == itemGroup && element == stopAt) return pos + 8;
            const std::uint32_t key = std::uint32_t(group) << 16 | element;
            if (!first && key <= previous)
                return fail(tagName(group, element, pos) + " is out of order (tags must ascend)");
            previous = key;
            first = false;
            if (depth == 0 && group == 0x7FE0 && element == 0x0010) pixelData = true;
            pos = one(pos, end, explicitVr, depth);
        }
        if (problem.empty() && stopAt != 0) fail("an item is not terminated before the end of the file");
        return pos;
    }

    /// The element at `pos`; returns the position after it.
    std::uint64_t one(std::uint64_t pos, std::uint64_t end, bool explicitVr, int depth)
    {
        if (depth > 64) return fail("sequences nested more than 64 deep");
        std::uint16_t group = 0, element = 0;
        if (!tag(pos, group, element)) return fail("truncated tag at byte " + std::to_string(pos));
        const std::uint64_t at = pos;
        if (group == itemGroup) return fail("misplaced item or delimiter " + tagName(group, element, at));
        std::uint32_t length = 0;
        enum class Content { Value, DataSets, Fragments } content = Content::Value;
        bool implicitInside = !explicitVr;
        if (explicitVr) {
            char vr[3] = {};
            if (!bytes(pos + 4, vr, 2)) return fail("truncated " + tagName(group, element, at));
            // Every VR of the standard (PS3.5 6.2); anything else makes GDCM misread the lengths
            // (it grew to 2.2 GB on a "UQ").
            static const char* const known[] = {"AE", "AS", "AT", "CS", "DA", "DS", "DT", "FD", "FL", "IS", "LO", "LT",
                                                "OB", "OD", "OF", "OL", "OV", "OW", "PN", "SH", "SL", "SQ", "SS", "ST",
                                                "SV", "TM", "UC", "UI", "UL", "UN", "UR", "US", "UT", "UV"};
            bool valid = false;
            for (const char* k : known) valid = valid || std::strcmp(vr, k) == 0;
            if (!valid) return fail(tagName(group, element, at) + " has an unknown VR");
            static const char* const longForms[] = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ", "SV", "UC", "UN", "UR", "UT", "UV"};
            bool longForm = false;
            for (const char* l : longForms) longForm = longForm || std::strcmp(vr, l) == 0;
            if (std::strcmp(vr, "SQ") == 0) content = Content::DataSets;
            if (std::strcmp(vr, "UN") == 0) content = Content::DataSets, implicitInside = true;
            if (std::strcmp(vr, "OB") == 0 || std::strcmp(vr, "OW") == 0) content = Content::Fragments;
            if (longForm) {
                if (!u32(pos + 8, length)) return fail("truncated " + tagName(group, element, at));
                pos += 12;
            } else {
                std::uint16_t shortLength = 0;
                if (!u16(pos + 6, shortLength)) return fail("truncated " + tagName(group, element, at));
                length = shortLength;
                pos += 8;
            }
        } else {
            if (!u32(pos + 4, length)) return fail("truncated " + tagName(group, element, at));
            pos += 8;
            content = group == 0x7FE0 ? Content::Fragments : Content::DataSets;  // only these may be undefined
        }
        if (length != undefinedLength) {
            if (pos + length > end)
                return fail(tagName(group, element, at) + " claims " + std::to_string(length) + " bytes; " + left(pos, end));
            return pos + length;
        }
        if (content == Content::Value) return fail(tagName(group, element, at) + " has an undefined length");
        // Items up to the sequence delimiter: data sets (a sequence) or opaque fragments (pixel data).
        while (problem.empty()) {
            std::uint16_t g = 0, e = 0;
            std::uint32_t itemLength = 0;
            const std::uint64_t itemAt = pos;
            if (!tag(pos, g, e) || !u32(pos + 4, itemLength))
                return fail(tagName(group, element, at) + ": its items run past the end of the file");
            pos += 8;
            if (g == itemGroup && e == sequenceEnd) return pos;
            if (g != itemGroup || e != item) return fail("expected an item in " + tagName(group, element, at) + ", found " + tagName(g, e, itemAt));
            if (itemLength == undefinedLength) {
                if (content != Content::DataSets) return fail("pixel-data fragment at byte " + std::to_string(itemAt) + " has an undefined length");
                pos = dataSet(pos, end, !implicitInside, itemEnd, depth + 1);
            } else if (pos + itemLength > end) {
                return fail("item at byte " + std::to_string(itemAt) + " claims " + std::to_string(itemLength) + " bytes; " + left(pos, end));
            } else {
                if (content == Content::DataSets) dataSet(pos, pos + itemLength, !implicitInside, 0, depth + 1);
                pos += itemLength;
            }
        }
        return pos;
    }

private:
    std::uint64_t fail(const std::string& why)
    {
        if (problem.empty()) problem = why;
        return _size;
    }
    static std::string left(std::uint64_t pos, std::uint64_t end)
    {
        return std::to_string(end > pos ? end - pos : 0) + " are left";
    }
    bool bytes(std::uint64_t pos, char* out, std::size_t n)
    {
        if (pos + n > _size) return false;
        _in.clear();
        _in.seekg(std::streamoff(pos));
        return bool(_in.read(out, std::streamsize(n)));
    }
    bool u16(std::uint64_t pos, std::uint16_t& v)
    {
        unsigned char b[2];
        if (!bytes(pos, reinterpret_cast<char*>(b), 2)) return false;
        v = bigEndian ? std::uint16_t(b[0] << 8 | b[1]) : std::uint16_t(b[1] << 8 | b[0]);
        return true;
    }
    bool u32(std::uint64_t pos, std::uint32_t& v)
    {
        unsigned char b[4];
        if (!bytes(pos, reinterpret_cast<char*>(b), 4)) return false;
        v = bigEndian ? (std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | b[3])
                      : (std::uint32_t(b[3]) << 24 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[1]) << 8 | b[0]);
        return true;
    }
    bool tag(std::uint64_t pos, std::uint16_t& group, std::uint16_t& element)
    {
        return u16(pos, group) && u16(pos + 2, element);
    }

    std::ifstream& _in;
    std::uint64_t _size;
};

}  // namespace

Structure structureProblem(const std::string& file)
{
    Structure result;
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (!in) {
        result.problem = "cannot open";
        return result;
    }
    const std::uint64_t size = std::uint64_t(in.tellg());
    char magic[4] = {};
    in.seekg(128);
    result.part10 = size >= 132 && in.read(magic, 4) && std::memcmp(magic, "DICM", 4) == 0;
    Walker walker(in, size);
    if (!result.part10) {
        // A bare data set: explicit VR when the first element carries one (two capital letters).
        char head[6] = {};
        in.clear();
        in.seekg(0);
        if (size < 8 || !in.read(head, 6)) {
            result.problem = "too short for a data element";
            return result;
        }
        const bool explicitVr = head[4] >= 'A' && head[4] <= 'Z' && head[5] >= 'A' && head[5] <= 'Z';
        walker.dataSet(0, size, explicitVr, 0, 0);
        result.problem = walker.problem;
        result.pixelData = walker.pixelData;
        return result;
    }

    // The file meta group (0002,xxxx): explicit VR little endian, whatever the data set uses.
    std::uint64_t pos = 132;
    std::string transferSyntax;
    while (pos + 8 <= size) {
        unsigned char head[4];
        in.clear();
        in.seekg(std::streamoff(pos));
        if (!in.read(reinterpret_cast<char*>(head), 4)) break;
        const std::uint16_t group = std::uint16_t(head[1] << 8 | head[0]);
        const std::uint16_t element = std::uint16_t(head[3] << 8 | head[2]);
        if (group != 0x0002) break;
        // The meta group holds plain values: a sequence or an undefined length there makes GDCM
        // 3.0 abort ("If any boozoo ever write a SQ in the meta header").
        char vr[3] = {};
        in.clear();
        in.seekg(std::streamoff(pos + 4));
        in.read(vr, 2);
        unsigned char longLength[4] = {0, 0, 0, 0};
        in.clear();
        in.seekg(std::streamoff(pos + 8));
        in.read(reinterpret_cast<char*>(longLength), 4);
        const bool undefined = (std::strcmp(vr, "OB") == 0 || std::strcmp(vr, "UN") == 0 || std::strcmp(vr, "OW") == 0) &&
                               longLength[0] == 0xFF && longLength[1] == 0xFF && longLength[2] == 0xFF && longLength[3] == 0xFF;
        if (std::strcmp(vr, "SQ") == 0 || undefined) {
            result.problem = "file meta information: (0002," + hex4(element) + ") is a sequence or has an undefined length";
            return result;
        }
        const std::uint64_t next = walker.one(pos, size, true, 0);
        if (!walker.problem.empty()) {
            result.problem = "file meta information: " + walker.problem;
            return result;
        }
        if (element == 0x0010 && next >= pos + 8 && next - pos - 8 <= 64) {  // transfer syntax UID
            transferSyntax.resize(next - pos - 8);
            in.clear();
            in.seekg(std::streamoff(pos + 8));
            in.read(transferSyntax.data(), std::streamsize(transferSyntax.size()));
            while (!transferSyntax.empty() && (transferSyntax.back() == '\0' || transferSyntax.back() == ' '))
                transferSyntax.pop_back();
        }
        pos = next;
    }
    if (pos == 132) {
        result.problem = "no file meta information (group 0002) after the DICM prefix";
        return result;
    }
    if (transferSyntax.empty()) {
        result.problem = "file meta information without a transfer syntax (0002,0010)";
        return result;
    }
    if (transferSyntax == "1.2.840.10008.1.2.1.99") {  // deflated data set: not walkable here
        result.pixelData = true;
        return result;
    }
    const bool implicitVr = transferSyntax == "1.2.840.10008.1.2";
    walker.bigEndian = transferSyntax == "1.2.840.10008.1.2.2";
    walker.dataSet(pos, size, !implicitVr, 0, 0);
    result.problem = walker.problem;
    result.pixelData = walker.pixelData;
    return result;
}

}  // namespace volren::dicom
