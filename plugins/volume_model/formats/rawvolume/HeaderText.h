#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace volren::rawvolume {

/// Up to `maxBytes` bytes from the start of `path`; throws std::runtime_error("path: reason").
std::string readFileHead(const std::string& path, std::size_t maxBytes);

/// `text` without leading and trailing white space.
std::string trim(const std::string& text);
/// Lower-case copy of `text`.
std::string lowerCase(std::string text);
/// White-space separated words of `text`.
std::vector<std::string> splitWords(const std::string& text);
/// Parses the whole of `text` as a decimal integer; false on anything else or overflow.
bool parseInteger(const std::string& text, long long& out);

/// `file` as given when absolute, else relative to the folder of `headerPath`.
std::string resolveDataFile(const std::string& headerPath, const std::string& file);

/// File names from a printf-style pattern with one integer conversion (`%d`, `%03d`, `%i`,
/// `%u`) for first, first+step, ... up to last; throws std::runtime_error naming `name`.
std::vector<std::string> expandFilePattern(const std::string& pattern, long long first, long long last,
                                           long long step, const std::string& name);

}  // namespace volren::rawvolume
