#include <volume_model/ParseNumber.h>

#include <cmath>
#include <cstdlib>

namespace volren {

bool parseFiniteNumber(const std::string& text, double& out)
{
    if (text.empty()) return false;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (!end || *end != '\0' || !std::isfinite(value)) return false;
    out = value;
    return true;
}

}  // namespace volren
