#pragma once
#include <osgDB/Options>

#include <string>

namespace volren::serializers {

// Files a scene refers to (volumes) are written relative to the scene file and found again
// next to it. OSG's .osgt/.osgb/.osgx reader and writer put the scene file's folder first in
// the options' database path list; that is the only place a serializer learns where the
// scene file is.

/// Folder of the scene file being read or written ("" when unknown: a stream without a file).
std::string sceneFolder(const osgDB::Options* options);

/// `file` as written into the scene: relative to sceneFolder() when that is known, else absolute.
std::string pathForScene(const std::string& file, const osgDB::Options* options);

/// The file that `path` (as written in a scene) names: absolute paths as they are, relative ones
/// against the scene folder first, then OSG's data file path list ($OSG_FILE_PATH, then
/// volren's data folders: findDataFileFrom); "" when there is none.
/// Patterns (`slices/s*.tif`) are not looked up, only made absolute against the scene folder.
std::string resolveFromScene(const std::string& path, const osgDB::Options* options);

}  // namespace volren::serializers
