#pragma once
#include <string>

namespace volren {

/// Parses the whole of `text` as a finite number (no trailing characters, no NaN/Inf).
bool parseFiniteNumber(const std::string& text, double& out);

}  // namespace volren
