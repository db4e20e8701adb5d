#include "NumberedFiles.h"

#include <osgDB/FileNameUtils>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fnmatch.h>
#include <stdexcept>
#include <system_error>
#include <tuple>

namespace volren::stack {

namespace fs = std::filesystem;

namespace {

/// Text before the last run of digits of the stem (the whole stem when it has no digits).
std::string slicePrefix(const std::string& fileName)
{
    const std::string stem = osgDB::getNameLessExtension(fileName);
    std::size_t end = stem.size();
    while (end > 0 && !std::isdigit(static_cast<unsigned char>(stem[end - 1]))) --end;
    if (end == 0) return stem;
    std::size_t begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    return stem.substr(0, begin);
}

}  // namespace

bool isFilePattern(const std::string& path)
{
    return osgDB::getSimpleFileName(path).find_first_of("*?") != std::string::npos;
}

long long sliceNumber(const std::string& fileName)
{
    const std::string stem = osgDB::getNameLessExtension(osgDB::getSimpleFileName(fileName));
    std::size_t end = stem.size();
    while (end > 0 && !std::isdigit(static_cast<unsigned char>(stem[end - 1]))) --end;
    if (end == 0) return -1;
    std::size_t begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    const std::string digits = stem.substr(begin, std::min<std::size_t>(end - begin, 18));
    return std::stoll(digits);
}

std::vector<std::string> numberedFiles(const std::string& dirOrPattern, const std::vector<std::string>& extensions)
{
    const bool pattern = isFilePattern(dirOrPattern);
    std::string dir = pattern ? osgDB::getFilePath(dirOrPattern) : dirOrPattern;
    if (dir.empty()) dir = ".";
    const std::string glob = pattern ? osgDB::getSimpleFileName(dirOrPattern) : std::string();

    std::error_code ec;
    fs::directory_iterator it(dir, ec);
    if (ec) throw std::runtime_error(dirOrPattern + ": cannot read directory: " + ec.message());
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : it) {
        std::error_code typeError;
        if (!entry.is_regular_file(typeError)) continue;
        const std::string name = entry.path().filename().string();
        if (pattern) {
            if (fnmatch(glob.c_str(), name.c_str(), 0) != 0) continue;
        } else {
            const std::string ext = osgDB::getLowerCaseFileExtension(name);
            if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) continue;
        }
        names.push_back(name);
    }
    if (names.empty()) {
        std::string what;
        for (const std::string& ext : extensions) what += (what.empty() ? "*." : ", *.") + ext;
        throw std::runtime_error(dirOrPattern + (pattern ? ": no file matches the pattern" : ": empty directory: no " + what + " files"));
    }
    std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
        return std::make_tuple(slicePrefix(a), sliceNumber(a), a) < std::make_tuple(slicePrefix(b), sliceNumber(b), b);
    });
    std::vector<std::string> paths;
    for (const std::string& name : names) paths.push_back(osgDB::concatPaths(dir, name));
    return paths;
}

}  // namespace volren::stack
