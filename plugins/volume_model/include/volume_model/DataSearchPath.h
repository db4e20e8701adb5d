#pragma once
#include <string>
#include <vector>

namespace volren {

// Scenes name their data files (volumes, models) by relative names, found as OSG finds data:
// next to the scene file, then in OSG's data file path list ($OSG_FILE_PATH first, as for
// OpenSceneGraph-Data), to which volren appends its own data folders.

/// volren's own data folders: share/volren/data of the tree this library lies in and, when that
/// is a build tree of a checkout with `../shared/data` beside it, that folder.
std::vector<std::string> volrenDataFolders();

/// Appends volrenDataFolders() to osgDB's data file path list (after $OSG_FILE_PATH), once.
void registerDataPath();

/// The file a relative `name` names: in `folder` (a scene file's folder; skipped when empty),
/// then along osgDB's data file path list. Absolute names are returned when they exist. "" when
/// not found.
std::string findDataFileFrom(const std::string& name, const std::string& folder);

/// Every folder findDataFileFrom searches, for "not found" messages: "'a', 'b', 'c'".
std::string searchedFolders(const std::string& folder);

}  // namespace volren
