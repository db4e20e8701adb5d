#include "HeaderText.h"

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace volren::rawvolume {

std::string readFileHead(const std::string& path, std::size_t maxBytes)
{
    if (osgDB::fileType(path) == osgDB::DIRECTORY) throw std::runtime_error(path + ": is a directory, not a volume file");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open for reading: " + std::strerror(errno));
    std::error_code ec;  // no buffer of maxBytes for a short file (headers are read per load)
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    std::string text(ec ? maxBytes : std::size_t(std::min<std::uintmax_t>(size, maxBytes)), '\0');
    in.read(&text[0], std::streamsize(text.size()));
    if (in.bad()) throw std::runtime_error(path + ": read error");
    text.resize(std::size_t(in.gcount()));
    return text;
}

std::string trim(const std::string& text)
{
    std::size_t b = 0, e = text.size();
    while (b < e && std::isspace(static_cast<unsigned char>(text[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(text[e - 1]))) --e;
    return text.substr(b, e - b);
}

std::string lowerCase(std::string text)
{
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::vector<std::string> splitWords(const std::string& text)
{
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        std::size_t j = i;
        while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
        if (j > i) words.push_back(text.substr(i, j - i));
        i = j;
    }
    return words;
}

bool parseInteger(const std::string& text, long long& out)
{
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (errno == ERANGE || !end || *end != '\0') return false;
    out = v;
    return true;
}

std::string resolveDataFile(const std::string& headerPath, const std::string& file)
{
    if (osgDB::isAbsolutePath(file)) return file;
    const std::string dir = osgDB::getFilePath(headerPath);
    return dir.empty() ? file : osgDB::concatPaths(dir, file);
}

std::vector<std::string> expandFilePattern(const std::string& pattern, long long first, long long last, long long step,
                                           const std::string& name)
{
    // Exactly one conversion: % [0] [width] (d|i|u); "%%" stands for a literal percent sign.
    std::string prefix, suffix, conversion;
    bool found = false;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        std::string& out = found ? suffix : prefix;
        if (pattern[i] != '%') {
            out += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            ++i;
            continue;
        }
        if (found) throw std::runtime_error(name + ": file name pattern '" + pattern + "' has more than one conversion");
        std::size_t j = i + 1;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
        if (j >= pattern.size() || (pattern[j] != 'd' && pattern[j] != 'i' && pattern[j] != 'u') || j - i > 4)
            throw std::runtime_error(name + ": file name pattern '" + pattern + "' needs one integer conversion such as %d or %03d");
        conversion = pattern.substr(i, j - i) + "lld";
        found = true;
        i = j;
    }
    if (!found) throw std::runtime_error(name + ": file name pattern '" + pattern + "' has no %d conversion");
    if (step == 0 || (step > 0 && last < first) || (step < 0 && last > first))
        throw std::runtime_error(name + ": file name range " + std::to_string(first) + " .. " + std::to_string(last) +
                                 " step " + std::to_string(step) + " is empty or endless");
    const unsigned long long count = (unsigned long long)((last - first) / step) + 1;
    if (count > 1000000) throw std::runtime_error(name + ": file name range gives " + std::to_string(count) + " files (limit 1000000)");
    std::vector<std::string> files;
    for (unsigned long long k = 0; k < count; ++k) {
        char number[64];
        std::snprintf(number, sizeof(number), conversion.c_str(), first + (long long)k * step);
        files.push_back(prefix + number + suffix);
    }
    return files;
}

}  // namespace volren::rawvolume
