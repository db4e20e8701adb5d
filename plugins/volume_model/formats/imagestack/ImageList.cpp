#include "ImageList.h"

#include <osgDB/FileNameUtils>

#include <fstream>
#include <stdexcept>

namespace volren::imagestack {

std::vector<std::string> readImageList(const std::string& listPath)
{
    std::ifstream in(listPath);
    if (!in) throw std::runtime_error(listPath + ": cannot open the image list");
    const std::string folder = osgDB::getFilePath(listPath);
    std::vector<std::string> paths;
    std::string line;
    while (std::getline(in, line)) {
        const std::size_t begin = line.find_first_not_of(" \t\r");
        if (begin == std::string::npos || line[begin] == '#') continue;
        const std::size_t end = line.find_last_not_of(" \t\r");
        const std::string entry = line.substr(begin, end - begin + 1);
        paths.push_back(osgDB::isAbsolutePath(entry) || folder.empty() ? entry : osgDB::concatPaths(folder, entry));
    }
    if (in.bad()) throw std::runtime_error(listPath + ": read error in the image list");
    if (paths.empty()) throw std::runtime_error(listPath + ": zero images: the list names no image files");
    return paths;
}

}  // namespace volren::imagestack
