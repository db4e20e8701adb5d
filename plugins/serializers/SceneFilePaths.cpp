#include "SceneFilePaths.h"

#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <filesystem>
#include <system_error>

namespace volren::serializers {

namespace fs = std::filesystem;

namespace {

/// Absolute form of `path` with symbolic links resolved where the path exists.
fs::path normalised(const std::string& path)
{
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) p = fs::absolute(path, ec).lexically_normal();
    return p;
}

}  // namespace

std::string sceneFolder(const osgDB::Options* options)
{
    if (!options || options->getDatabasePathList().empty()) return {};
    return options->getDatabasePathList().front();
}

std::string pathForScene(const std::string& file, const osgDB::Options* options)
{
    if (file.empty()) return file;
    const fs::path target = normalised(file);
    if (!options || options->getDatabasePathList().empty()) return target.string();
    // An empty folder is the current directory (a scene file named without a folder).
    const std::string folder = sceneFolder(options);
    const fs::path base = normalised(folder.empty() ? std::string(".") : folder);
    const fs::path relative = target.lexically_relative(base);
    return relative.empty() ? target.string() : relative.generic_string();
}

std::string resolveFromScene(const std::string& path, const osgDB::Options* options)
{
    if (path.empty()) return {};
    if (path.find_first_of("*?") != std::string::npos) {
        if (osgDB::isAbsolutePath(path)) return path;
        return normalised(osgDB::concatPaths(sceneFolder(options), path)).string();
    }
    if (osgDB::isAbsolutePath(path)) return osgDB::fileExists(path) ? path : std::string();
    // Next to the scene first (findDataFile may prefer a same-named file in the working directory).
    const std::string beside = osgDB::concatPaths(sceneFolder(options), path);
    if (osgDB::fileExists(beside)) return normalised(beside).string();
    std::string found = osgDB::findDataFile(path, options);
    if (found.empty()) {  // volren's own data (the default scene's head)
        const std::string shared = osgDB::concatPaths(osgDB::concatPaths(shareDirectory(), "data"), path);
        if (osgDB::fileExists(shared)) found = shared;
    }
    return found.empty() ? found : normalised(found).string();
}

}  // namespace volren::serializers
