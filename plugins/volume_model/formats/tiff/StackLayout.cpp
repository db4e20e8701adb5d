#include "StackLayout.h"

#include <algorithm>
#include <limits>

namespace volren::tiff {

std::size_t StackLayout::pageCount() const
{
    const std::size_t max = std::numeric_limits<std::size_t>::max();
    if (channels == 0 || slices == 0 || frames == 0) return 0;
    if (channels > max / slices || channels * slices > max / frames) return 0;
    return channels * slices * frames;
}

void StackLayout::coordinates(std::size_t page, std::size_t& c, std::size_t& z, std::size_t& t) const
{
    c = z = t = 0;
    for (char axis : order) {
        std::size_t& v = axis == 'C' ? c : axis == 'Z' ? z : t;
        const std::size_t n = axis == 'C' ? channels : axis == 'Z' ? slices : frames;
        v = page % n;
        page /= n;
    }
}

bool parseDimensionOrder(const std::string& text, std::string& order)
{
    if (text.size() != 5 || text.compare(0, 2, "XY") != 0) return false;
    std::string rest = text.substr(2);
    std::string sorted = rest;
    std::sort(sorted.begin(), sorted.end());
    if (sorted != "CTZ") return false;
    order = rest;
    return true;
}

}  // namespace volren::tiff
