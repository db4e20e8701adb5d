#include <volume_model/DataSearchPath.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <algorithm>
#include <mutex>

namespace volren {

std::vector<std::string> volrenDataFolders()
{
    std::vector<std::string> folders{osgDB::concatPaths(shareDirectory(), "data")};
    // A build tree (not an install) of a checkout also finds the shared datasets beside it.
    const std::string buildShare = osgDB::getRealPath(VOLREN_BUILD_SHARE_DIR);
    if (osgDB::getRealPath(shareDirectory()) == buildShare && osgDB::fileType(VOLREN_CHECKOUT_DATA_DIR) == osgDB::DIRECTORY)
        folders.push_back(osgDB::getRealPath(VOLREN_CHECKOUT_DATA_DIR));
    return folders;
}

void registerDataPath()
{
    static std::once_flag once;
    std::call_once(once, [] {
        osgDB::FilePathList& paths = osgDB::Registry::instance()->getDataFilePathList();
        for (const std::string& folder : volrenDataFolders())
            if (std::find(paths.begin(), paths.end(), folder) == paths.end()) paths.push_back(folder);
    });
}

std::string findDataFileFrom(const std::string& name, const std::string& folder)
{
    if (name.empty()) return {};
    if (osgDB::isAbsolutePath(name)) return osgDB::fileExists(name) ? name : std::string();
    registerDataPath();
    // The scene's folder first (osgDB::findDataFile would prefer a same-named file in the
    // working directory), then the data file path list, in order.
    if (!folder.empty()) {
        const std::string beside = osgDB::concatPaths(folder, name);
        if (osgDB::fileExists(beside)) return beside;
    } else if (osgDB::fileExists(name)) {
        return name;
    }
    return osgDB::findFileInPath(name, osgDB::Registry::instance()->getDataFilePathList());
}

std::string searchedFolders(const std::string& folder)
{
    registerDataPath();
    std::string text = "'" + (folder.empty() ? osgDB::getCurrentWorkingDirectory() : folder) + "'";
    for (const std::string& path : osgDB::Registry::instance()->getDataFilePathList())
        if (!path.empty() && path != folder) text += ", '" + path + "'";
    return text;
}

}  // namespace volren
