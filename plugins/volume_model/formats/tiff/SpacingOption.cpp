#include "SpacingOption.h"

#include <volume_model/ParseNumber.h>

#include <sstream>
#include <stdexcept>

namespace volren::stack {

std::optional<osg::Vec3d> spacingOption(const osgDB::Options* options)
{
    if (!options) return std::nullopt;
    std::istringstream tokens(options->getOptionString());
    std::string token;
    while (tokens >> token) {
        if (token.rfind("spacing=", 0) != 0) continue;
        std::istringstream parts(token.substr(8));
        osg::Vec3d spacing;
        std::string part;
        int n = 0;
        while (std::getline(parts, part, ',')) {
            double v = 0.0;
            if (n >= 3 || !parseFiniteNumber(part, v) || !(v > 0.0)) n = 99;
            else spacing[n++] = v;
        }
        if (n != 3) throw std::runtime_error("bad option '" + token + "': expected spacing=x,y,z with three positive numbers");
        return spacing;
    }
    return std::nullopt;
}

}  // namespace volren::stack
