// Bricks of a volume's mip levels in a pool texture and their page table (VolumeStorage/bricked).
#include <volume_renderer/BrickPool.h>
#include <volume_renderer/VolumeMipChain.h>
#include <volume_renderer/VolumeTextures.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace volren {

std::size_t BrickLayout::brickCount(int level) const
{
    const osg::Vec3i& b = levels.at(std::size_t(level)).bricks;
    return std::size_t(b.x()) * std::size_t(b.y()) * std::size_t(b.z());
}

BrickLayout brickLayout(const std::vector<osg::Vec3i>& levelDims, int brickSize)
{
    if (brickSize < 2) throw std::invalid_argument("brick size " + std::to_string(brickSize) + " is below 2 voxels");
    if (levelDims.empty()) throw std::invalid_argument("a bricked volume needs at least one level");
    BrickLayout layout;
    layout.brickSize = brickSize;
    int z = 0, x = 1, y = 1;
    for (const osg::Vec3i& d : levelDims) {
        const osg::Vec3i b((d.x() + brickSize - 1) / brickSize, (d.y() + brickSize - 1) / brickSize,
                           (d.z() + brickSize - 1) / brickSize);
        layout.levels.push_back({d, b, z});
        z += b.z();
        x = std::max(x, b.x());
        y = std::max(y, b.y());
    }
    layout.tableSize = osg::Vec3i(x, y, z);
    return layout;
}

BrickLayout brickLayout(const osg::Vec3i& dims, int brickSize)
{
    std::vector<osg::Vec3i> levels;
    for (int level = 0; level < mipLevelCount(dims); ++level) levels.push_back(mipDims(dims, level));
    return brickLayout(levels, brickSize);
}

osg::Vec3i poolSlotsFor(std::size_t wanted, int slotTexels, int maxTextureSize)
{
    const std::size_t perAxis = std::size_t(std::max(0, maxTextureSize / slotTexels));
    if (perAxis == 0)
        throw std::invalid_argument("a brick of " + std::to_string(slotTexels) + " texels exceeds the largest 3D texture (" +
                                    std::to_string(maxTextureSize) + ")");
    wanted = std::max<std::size_t>(wanted, 1);
    const std::size_t x = std::min(perAxis, std::size_t(std::ceil(std::cbrt(double(wanted)))));
    const std::size_t rest = (wanted + x - 1) / x;
    const std::size_t y = std::min(perAxis, std::size_t(std::ceil(std::sqrt(double(rest)))));
    const std::size_t z = std::min(perAxis, (rest + y - 1) / y);
    return osg::Vec3i(int(x), int(y), int(z));
}

namespace {

/// Whether a brick's texel range (with its border) is one value: lo == hi, or NaN only.
bool isConstant(const MacrocellGrid& g, std::size_t i)
{
    return g.lo[i] == g.hi[i] || g.lo[i] > g.hi[i];
}

/// Whether the box [lo, hi] (texture space) may be seen through the sides of the view of `m`
/// (texture -> clip space). Near and far are not tested: OSG fits them after culling.
bool mayBeSeen(const osg::Matrixd& m, const osg::Vec3d& lo, const osg::Vec3d& hi)
{
    int outside[4] = {0, 0, 0, 0}, behind = 0;
    for (int c = 0; c < 8; ++c) {
        const osg::Vec4d p = osg::Vec4d(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z(), 1.0) * m;
        if (p.w() <= 0.0) {
            ++behind;
            continue;
        }
        for (int a = 0; a < 2; ++a) {
            outside[2 * a] += p[a] < -p.w();
            outside[2 * a + 1] += p[a] > p.w();
        }
    }
    if (behind == 8) return false;  // wholly behind the eye
    if (behind > 0) return true;    // around the eye: kept
    return std::none_of(std::begin(outside), std::end(outside), [](int n) { return n == 8; });
}

}  // namespace

BrickVisibility brickVisibility(const BrickLayout& layout, const osg::Matrixd& textureToClip)
{
    return [&layout, m = textureToClip](int level, const osg::Vec3i& b) {
        const BrickLevel& l = layout.levels[std::size_t(level)];
        const int s = layout.brickSize;
        osg::Vec3d lo, hi;
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max(0.0, double(b[a] * s - 1) / l.dims[a]);
            hi[a] = std::min(1.0, double((b[a] + 1) * s + 1) / l.dims[a]);
        }
        return mayBeSeen(m, lo, hi);
    };
}

BrickPlan planBricks(const BrickLayout& layout, const std::vector<MacrocellGrid>& ranges, int firstLevel,
                     std::size_t capacity, bool constantBricks, const BrickVisibility& visible, const BrickHiding& hidden)
{
    BrickPlan plan;
    const int levels = int(layout.levels.size());
    plan.firstLevel = std::clamp(firstLevel, 0, levels - 1);
    for (int level = levels - 1; level >= plan.firstLevel; --level) {
        const BrickLevel& l = layout.levels[std::size_t(level)];
        const MacrocellGrid* g = std::size_t(level) < ranges.size() && ranges[std::size_t(level)].size() ? &ranges[std::size_t(level)] : nullptr;
        if (g && g->cells != l.bricks) throw std::logic_error("brick ranges of level " + std::to_string(level) + " do not match its bricks");
        std::vector<BrickId> slotted;
        std::vector<std::pair<BrickId, float>> constant;
        for (int z = 0; z < l.bricks.z(); ++z)
            for (int y = 0; y < l.bricks.y(); ++y)
                for (int x = 0; x < l.bricks.x(); ++x) {
                    const osg::Vec3i b(x, y, z);
                    if (level != levels - 1 && visible && !visible(level, b)) continue;
                    if (hidden)
                        if (const std::optional<float> value = hidden(level, b)) {
                            constant.emplace_back(BrickId{level, b}, *value);
                            continue;
                        }
                    if (g && constantBricks && isConstant(*g, g->index(x, y, z))) {
                        const std::size_t i = g->index(x, y, z);
                        constant.emplace_back(BrickId{level, b}, g->lo[i] > g->hi[i] ? std::nanf("") : g->lo[i]);
                    } else {
                        slotted.push_back({level, b});
                    }
                }
        if (plan.slotted.size() + slotted.size() > capacity) {
            if (level == levels - 1)
                throw std::invalid_argument("the memory budget holds " + std::to_string(capacity) +
                                            " bricks, not even the coarsest level's " + std::to_string(slotted.size()));
            break;
        }
        plan.slotted.insert(plan.slotted.end(), slotted.begin(), slotted.end());
        plan.constant.insert(plan.constant.end(), constant.begin(), constant.end());
        plan.finest = level;
    }
    return plan;
}

}  // namespace volren
