#include <volume_model/ImageJLut.h>
#include <volume_model/ParseNumber.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace volren {

namespace {

constexpr int entries = 256;
constexpr std::size_t rawSize = 3 * entries;      // 768
constexpr std::size_t nihHeaderSize = 32;         // "ICOL", version, nColors, start, end, filler
constexpr std::size_t maxFileSize = 1024 * 1024;  // a text LUT is a few KiB

/// A LUT entry (0..255 components) at a position in [0, 255] of the table.
struct Entry
{
    double position;
    std::array<double, 3> rgb;
};

const char* const componentNames[] = {"red", "green", "blue"};

/// The three planes of `count` bytes each (reds, greens, blues) starting at `data`.
std::vector<Entry> planes(const unsigned char* data, int count)
{
    std::vector<Entry> table;
    for (int i = 0; i < count; ++i)
        // NIH Image LUTs with fewer colours: ImageJ stretches them, entry k of n landing at k * 256 / n.
        table.push_back({i * double(entries) / count, {double(data[i]), double(data[count + i]), double(data[2 * count + i])}});
    return table;
}

/// Whether `word` reads as a number at all (NaN and infinities included).
bool numeric(const std::string& word)
{
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    return end != word.c_str() && *end == '\0';
}

std::vector<Entry> textTable(const std::string& path, const std::string& bytes)
{
    int lineNo = 0;
    auto fail = [&](const std::string& why) { throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": " + why); };
    std::vector<Entry> table;
    std::size_t columns = 0;
    bool seenContent = false;
    std::size_t start = 0;
    while (start < bytes.size()) {
        std::size_t end = bytes.find('\n', start);
        if (end == std::string::npos) end = bytes.size();
        std::string line = bytes.substr(start, end - start);
        start = end + 1;
        ++lineNo;
        for (char& c : line)
            if (c == ',' || c == '\t' || c == '\r' || c == '\f' || c == '\v') c = ' ';
        std::vector<std::string> words;
        for (std::size_t at = line.find_first_not_of(' '); at != std::string::npos; at = line.find_first_not_of(' ', at)) {
            const std::size_t stop = std::min(line.find(' ', at), line.size());
            words.push_back(line.substr(at, stop - at));
            at = stop;
        }
        if (words.empty()) continue;
        const bool first = !seenContent;
        seenContent = true;
        if (first) {  // a heading ("Index Red Green Blue") when no word of it is a number
            bool heading = true;
            for (const std::string& w : words) heading = heading && !numeric(w);
            if (heading) continue;
        }
        if (words.size() != 3 && words.size() != 4)
            fail("expected 'r g b' or 'index r g b', found " + std::to_string(words.size()) + " words");
        if (columns == 0) columns = words.size();
        if (words.size() != columns)
            fail("expected " + std::to_string(columns) + " columns like the first row, found " + std::to_string(words.size()));
        if (table.size() == entries) fail("more than " + std::to_string(entries) + " rows (one per LUT entry)");
        const std::size_t skip = columns - 3;  // the index column: read as a number, not used (ImageJ ignores it)
        std::array<double, 3> rgb;
        for (std::size_t c = 0; c < columns; ++c) {
            double v = 0.0;
            const std::string what = c < skip ? std::string("index") : componentNames[c - skip];
            if (!parseFiniteNumber(words[c], v)) fail(what + " '" + words[c] + "' is not a finite number");
            if (c < skip) continue;
            if (v < 0.0 || v > 255.0) fail(what + " " + words[c] + " is outside 0..255");
            rgb[c - skip] = v;
        }
        table.push_back({double(table.size()), rgb});
    }
    if (table.size() != entries)
        fail("expected " + std::to_string(entries) + " rows (one per LUT entry), the file has " + std::to_string(table.size()));
    return table;
}

}  // namespace

osg::ref_ptr<TransferFunction> readImageJLut(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open lookup-table file");
    std::string bytes;
    char buffer[4096];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        bytes.append(buffer, std::size_t(in.gcount()));
        if (bytes.size() > maxFileSize)
            throw std::runtime_error(path + ": larger than " + std::to_string(maxFileSize) + " bytes, not a lookup table");
    }
    if (in.bad()) throw std::runtime_error(path + ": read error");
    const std::string forms = " (an ImageJ LUT is 768 bytes raw, 800 bytes with an NIH Image 'ICOL' header, or 256 text rows)";
    if (bytes.empty()) throw std::runtime_error(path + ": empty file" + forms);

    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    std::vector<Entry> table;
    if (bytes.size() == rawSize) {  // always raw, as in ImageJ (even when it starts "ICOL")
        table = planes(data, entries);
    } else if (bytes.compare(0, 4, "ICOL") == 0) {
        if (bytes.size() < nihHeaderSize)
            throw std::runtime_error(path + ": NIH Image LUT truncated in its 32-byte header (" + std::to_string(bytes.size()) + " bytes)");
        const int colours = (data[6] << 8) | data[7];  // big-endian, after "ICOL" and the version
        if (colours < 1 || colours > entries)
            throw std::runtime_error(path + ": NIH Image LUT header says " + std::to_string(colours) + " colours; expected 1..256");
        const std::size_t expected = nihHeaderSize + 3 * std::size_t(colours);
        if (bytes.size() != expected)
            throw std::runtime_error(path + ": NIH Image LUT of " + std::to_string(colours) + " colours is " +
                                     std::to_string(expected) + " bytes, the file has " + std::to_string(bytes.size()) +
                                     (bytes.size() < expected ? " (truncated)" : ""));
        table = planes(data + nihHeaderSize, colours);
    } else {
        for (unsigned char c : bytes)
            if (c == 0 || (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v'))
                throw std::runtime_error(path + ": " + std::to_string(bytes.size()) + " bytes of binary data" + forms);
        table = textTable(path, bytes);
    }

    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setName(path);
    for (const Entry& e : table)
        tf->setPoint(e.position, osg::Vec4(float(e.rgb[0] / 255.0), float(e.rgb[1] / 255.0), float(e.rgb[2] / 255.0),
                                           float(e.position / (entries - 1))));
    const Entry& last = table.back();
    if (last.position < entries - 1)  // ImageJ holds the last of fewer colours to the end of the table
        tf->setPoint(entries - 1, osg::Vec4(float(last.rgb[0] / 255.0), float(last.rgb[1] / 255.0), float(last.rgb[2] / 255.0), 1.0f));
    tf->setDomain(0.0, entries - 1);
    return tf;
}

}  // namespace volren
