#pragma once
#include <string>
#include <vector>

namespace volren::stack {

/// Whether `path`'s file name holds a wildcard (`*` or `?`): a pattern of slice files.
bool isFilePattern(const std::string& path);

/// The number that orders a slice file: the last run of digits in its name without extension
/// (-1 when there is none).
long long sliceNumber(const std::string& fileName);

/// Regular files of directory `dir` whose lower-case extension is one of `extensions`, or
/// those matching the wildcard pattern `dir/pattern`, sorted by the text before the number,
/// then numerically by sliceNumber, then by name. Throws std::runtime_error("path: reason")
/// when the directory cannot be read or nothing matches.
std::vector<std::string> numberedFiles(const std::string& dirOrPattern, const std::vector<std::string>& extensions);

}  // namespace volren::stack
