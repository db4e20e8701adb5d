#pragma once
#include <string>
#include <vector>

namespace volren::imagestack {

/// The image paths of a `.imgstack` list file: one path per line, relative to the list's
/// folder unless absolute; blank lines and lines starting with '#' are skipped. Throws
/// std::runtime_error("list: reason") when it cannot be read or names no image.
std::vector<std::string> readImageList(const std::string& listPath);

}  // namespace volren::imagestack
