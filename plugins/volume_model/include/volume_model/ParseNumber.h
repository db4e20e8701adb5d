#pragma once
#include <string>

namespace volren {

/// Parses the whole of `text` as a finite number (no trailing characters, no NaN/Inf).
bool parseFiniteNumber(const std::string& text, double& out);
/// The shortest text that reads back as `v` exactly ("nan" for NaN).
std::string shortestText(double v);

}  // namespace volren
