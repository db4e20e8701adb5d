#include <volume_model/LazyOpening.h>
#include <volume_model/ParseNumber.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace volren {

std::uint64_t LazyOpening::previewBudget() const
{
    return std::min(maxPreviewBytes, ramBudget / 8);
}

std::uint64_t physicalMemoryBytes()
{
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? std::uint64_t(pages) * std::uint64_t(pageSize) : 0;
}

LazyOpening lazyOpeningOf(const osgDB::Options* options)
{
    LazyOpening lazy;
    const std::uint64_t ram = physicalMemoryBytes();
    lazy.ramBudget = ram ? ram / 4 : std::numeric_limits<std::uint64_t>::max();
    std::istringstream words(options ? options->getOptionString() : std::string());
    for (std::string word; words >> word;) {
        if (word == "lazy") {
            lazy.requested = true;
        } else if (word.rfind("ramBudgetMB=", 0) == 0) {
            double mb = 0.0;
            if (!parseFiniteNumber(word.substr(12), mb) || mb < 0.0 || mb > 1e12)
                throw std::runtime_error("option " + word + ": the RAM budget must be a number of MiB >= 0");
            lazy.ramBudget = std::uint64_t(std::llround(mb * 1048576.0));
        }
    }
    return lazy;
}

std::uint64_t levelBytes(const BrickSource& source, int level)
{
    const osg::Vec3i d = source.levelDims(level);
    return std::uint64_t(d.x()) * std::uint64_t(d.y()) * std::uint64_t(d.z()) * voxelSize(source.type());
}

int previewLevelFor(const BrickSource& source, std::uint64_t budget)
{
    for (int level = 0; level < source.levelCount(); ++level)
        if (levelBytes(source, level) <= budget) return level;
    return source.levelCount() - 1;
}

}  // namespace volren
