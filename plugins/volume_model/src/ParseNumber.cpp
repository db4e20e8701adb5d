#include <volume_model/ParseNumber.h>

#include <charconv>
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

std::string shortestText(double v)
{
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof(text), v);
    return error == std::errc() ? std::string(text, end) : std::string("nan");
}

}  // namespace volren
