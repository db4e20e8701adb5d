#include "SceneFilePaths.h"

#include <volume_model/DataSearchPath.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <filesystem>
#include <system_error>

namespace volren::serializers {

namespace fs = std::filesystem;

namespace {

// Stock OSG tools load this plugin when a scene names a volren class: from then on volren's data
// folders follow $OSG_FILE_PATH on their data path too (for the models a scene names as well).
[[maybe_unused]] const bool dataPathRegistered = (registerDataPath(), true);

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
    const std::string found = findDataFileFrom(path, sceneFolder(options));
    return found.empty() ? found : normalised(found).string();
}

}  // namespace volren::serializers
