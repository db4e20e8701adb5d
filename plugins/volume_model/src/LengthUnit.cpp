#include <volume_model/LengthUnit.h>

#include <osg/ValueObject>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace volren {

std::string lengthUnitSymbol(const std::string& name)
{
    std::string n;
    for (char c : name)
        if (!std::isspace(static_cast<unsigned char>(c))) n += char(std::tolower(static_cast<unsigned char>(c)));
    for (const char* micro : {"\xC2\xB5", "\xCE\xBC"})  // MICRO SIGN, GREEK SMALL LETTER MU
        if (n.rfind(micro, 0) == 0) n = "u" + n.substr(2);
    if (n.empty() || n == "pixel" || n == "pixels" || n == "px" || n == "unit" || n == "units") return {};
    if (n == "um" || n == "micron" || n == "microns" || n == "micrometer" || n == "micrometre" || n == "micrometers" ||
        n == "micrometres")
        return "\xC2\xB5m";
    for (const auto& [symbol, stem] : std::array<std::pair<const char*, const char*>, 4>{
             {{"nm", "nanomet"}, {"mm", "millimet"}, {"cm", "centimet"}, {"m", "met"}}})
        if (n == symbol || n.rfind(stem, 0) == 0) return symbol;
    return name;
}

std::string lengthUnitOf(const Volume& volume)
{
    std::string unit;
    volume.getUserValue(spacingUnitKey, unit);
    return lengthUnitSymbol(unit);
}

std::string lengthLabel(double length, const std::string& unit)
{
    static const std::array<std::string, 4> ladder = {"nm", "\xC2\xB5m", "mm", "m"};
    auto round3 = [](double v) {  // to 3 significant digits
        if (v == 0.0 || !std::isfinite(v)) return v;
        const double scale = std::pow(10.0, 2.0 - std::floor(std::log10(std::abs(v))));
        return std::round(v * scale) / scale;
    };
    std::string u = unit;
    length = round3(length);
    auto at = std::find(ladder.begin(), ladder.end(), u);
    if (at != ladder.end() && length > 0.0 && std::isfinite(length)) {
        while (length >= 1000.0 && at + 1 != ladder.end()) length = round3(length / 1000.0), ++at;
        while (length < 1.0 && at != ladder.begin()) length = round3(length * 1000.0), --at;
        u = *at;
    }
    char number[64];
    std::snprintf(number, sizeof number, "%.12g", length);
    return u.empty() ? std::string(number) : std::string(number) + " " + u;
}

}  // namespace volren
