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

BrickLayout brickLayout(const osg::Vec3i& dims, int brickSize)
{
    if (brickSize < 2) throw std::invalid_argument("brick size " + std::to_string(brickSize) + " is below 2 voxels");
    BrickLayout layout;
    layout.brickSize = brickSize;
    int z = 0, x = 1, y = 1;
    for (int level = 0; level < mipLevelCount(dims); ++level) {
        const osg::Vec3i d = mipDims(dims, level);
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

/// Bricks of `g` that need a pool slot.
std::size_t slotsNeeded(const MacrocellGrid& g, bool constantBricks)
{
    std::size_t n = 0;
    for (std::size_t i = 0; i < g.size(); ++i) n += !(constantBricks && isConstant(g, i));
    return n;
}

}  // namespace

BrickResidency chooseResidency(const BrickLayout& layout, const std::vector<MacrocellGrid>& ranges, int firstLevel,
                               const osg::Vec3i& slots, std::size_t capacity, bool constantBricks)
{
    BrickResidency r;
    r.layout = layout;
    const int levels = int(layout.levels.size());
    r.firstLevel = std::clamp(firstLevel, 0, levels - 1);
    r.slots = slots;
    const osg::Vec3i& t = layout.tableSize;
    r.pageTable.assign(std::size_t(t.x()) * t.y() * t.z() * 4, 0.0f);
    for (int level = levels - 1; level >= r.firstLevel; --level) {
        const BrickLevel& l = layout.levels[std::size_t(level)];
        const MacrocellGrid& g = ranges.at(std::size_t(level));
        if (g.cells != l.bricks) throw std::logic_error("brick ranges of level " + std::to_string(level) + " do not match its bricks");
        const std::size_t needed = slotsNeeded(g, constantBricks);
        if (r.resident.size() + needed > capacity) {
            if (level == levels - 1)
                throw std::invalid_argument("the memory budget holds " + std::to_string(capacity) +
                                            " bricks, not even the coarsest level's " + std::to_string(needed));
            break;
        }
        for (int z = 0; z < l.bricks.z(); ++z)
            for (int y = 0; y < l.bricks.y(); ++y)
                for (int x = 0; x < l.bricks.x(); ++x) {
                    const std::size_t i = g.index(x, y, z);
                    float* e = &r.pageTable[((std::size_t(z + l.tableZ) * t.y() + y) * t.x() + x) * 4];
                    if (constantBricks && isConstant(g, i)) {
                        e[0] = g.lo[i] > g.hi[i] ? std::nanf("") : g.lo[i];
                        e[3] = float(PageEntry::Constant);
                        ++r.constant;
                        continue;
                    }
                    const std::size_t slot = r.resident.size();
                    e[0] = float(slot % std::size_t(slots.x()));
                    e[1] = float(slot / std::size_t(slots.x()) % std::size_t(slots.y()));
                    e[2] = float(slot / (std::size_t(slots.x()) * std::size_t(slots.y())));
                    e[3] = float(PageEntry::Resident);
                    r.resident.emplace_back(level, osg::Vec3i(x, y, z));
                }
        r.finestComplete = level;
    }
    return r;
}

namespace {

/// Block (0, 0) of `volume` at mip level `level` as a Volume of its own (level 0: `volume`).
osg::ref_ptr<const Volume> levelVolume(const Volume& volume, const std::vector<osg::ref_ptr<osg::Image>>& images, int level)
{
    if (level == 0) return &volume;
    const osg::Image& image = *images.at(std::size_t(level - 1));
    osg::ref_ptr<Volume> out = new Volume;
    out->allocate(volume.type(), osg::Vec3i(image.s(), image.t(), image.r()));
    std::memcpy(out->data(), image.data(), out->byteSize());
    out->setRescale(volume.rescaleSlope(), volume.rescaleIntercept());
    return out;
}

/// Copies brick `b` of `level` (with its one-voxel border, edge voxels repeated past the level's
/// edges) into slot `slot` of the pool image.
void copyBrick(const Volume& level, const osg::Vec3i& b, int brickSize, const osg::Vec3i& slot, osg::Image& pool)
{
    const std::size_t bytes = voxelSize(level.type());
    const osg::Vec3i& d = level.dims();
    const int texels = brickSize + 2;
    const osg::Vec3i origin = b * brickSize - osg::Vec3i(1, 1, 1);
    for (int z = 0; z < texels; ++z)
        for (int y = 0; y < texels; ++y) {
            const int vz = std::clamp(origin.z() + z, 0, d.z() - 1), vy = std::clamp(origin.y() + y, 0, d.y() - 1);
            const std::uint8_t* row = level.data() + (std::size_t(vz) * d.y() + vy) * d.x() * bytes;
            unsigned char* out = pool.data(slot.x() * texels, slot.y() * texels + y, slot.z() * texels + z);
            for (int x = 0; x < texels; ++x)
                std::memcpy(out + std::size_t(x) * bytes, row + std::size_t(std::clamp(origin.x() + x, 0, d.x() - 1)) * bytes,
                            bytes);
        }
}

}  // namespace

BrickStatistics BrickedVolume::statistics(const std::string& volume) const
{
    BrickStatistics s{.volume = volume,
                      .levelSampled = std::max(residency.firstLevel, residency.finestComplete),
                      .resident = residency.resident.size(),
                      .constant = residency.constant,
                      .poolBytes = poolBytes,
                      .budgetBytes = budgetBytes};
    for (int level = residency.firstLevel; level < s.levelSampled; ++level) s.missing += residency.layout.brickCount(level);
    return s;
}

BrickedVolume makeBrickedVolume(const Volume& volume, const std::vector<osg::ref_ptr<osg::Image>>& levelImages,
                                int firstLevel, int brickSize, std::size_t budgetBytes, int maxTextureSize, bool wide)
{
    const BrickLayout layout = brickLayout(volume.dims(), brickSize);
    const int levels = int(layout.levels.size());
    if (levels > 16) throw std::invalid_argument("a volume of more than 16 mip levels cannot be bricked");
    firstLevel = std::clamp(firstLevel, 0, levels - 1);
    if (int(levelImages.size()) < levels - 1) throw std::logic_error("bricking needs the whole mip chain");
    std::vector<osg::ref_ptr<const Volume>> volumes(static_cast<std::size_t>(levels));
    std::vector<MacrocellGrid> ranges(static_cast<std::size_t>(levels));
    // The ranges leave NaN voxels out, so a brick with some would pass for constant: with
    // non-finite voxels every brick is kept.
    const bool constantBricks = volume.nonFiniteCount() == 0;
    std::size_t wanted = 0;
    for (int level = firstLevel; level < levels; ++level) {
        volumes[std::size_t(level)] = levelVolume(volume, levelImages, level);
        ranges[std::size_t(level)] = buildMacrocellGrid(*volumes[std::size_t(level)], brickSize, 1);
        wanted += slotsNeeded(ranges[std::size_t(level)], constantBricks);
    }
    const bool widened = wide && voxelSize(volume.type()) == 1;
    const int texels = brickSize + 2;
    const std::size_t texelBytes = widened ? 2 : voxelSize(volume.type());
    const std::size_t slotBytes = std::size_t(texels) * texels * texels * texelBytes;
    const std::size_t byBudget = budgetBytes / slotBytes;
    osg::Vec3i slots = poolSlotsFor(std::min(wanted, byBudget), texels, maxTextureSize);
    const std::size_t capacity = std::min(byBudget, std::size_t(slots.x()) * slots.y() * slots.z());

    BrickedVolume out;
    out.residency = chooseResidency(layout, ranges, firstLevel, slots, capacity, constantBricks);
    // A pool no larger than the levels that fit: the same levels again in fewer slots.
    if (const std::size_t used = out.residency.resident.size(); used < capacity) {
        slots = poolSlotsFor(used, texels, maxTextureSize);
        out.residency = chooseResidency(layout, ranges, firstLevel, slots, used, constantBricks);
    }
    osg::ref_ptr<osg::Image> pool = new osg::Image;
    pool->allocateImage(slots.x() * texels, slots.y() * texels, slots.z() * texels, GL_RED, pixelTypeFor(volume.type()));
    std::memset(pool->data(), 0, pool->getTotalSizeInBytes());
    for (std::size_t s = 0; s < out.residency.resident.size(); ++s) {
        const auto& [level, brick] = out.residency.resident[s];
        const osg::Vec3i slot(int(s % std::size_t(slots.x())), int(s / std::size_t(slots.x()) % std::size_t(slots.y())),
                              int(s / (std::size_t(slots.x()) * std::size_t(slots.y()))));
        copyBrick(*volumes[std::size_t(level)], brick, brickSize, slot, *pool);
    }
    out.pool = makeVolumeTexture(volume, wide, pool.get());
    out.poolBytes = std::size_t(pool->s()) * pool->t() * pool->r() * texelBytes;
    out.budgetBytes = budgetBytes;

    const osg::Vec3i& t = layout.tableSize;
    osg::ref_ptr<osg::Image> table = new osg::Image;
    table->allocateImage(t.x(), t.y(), t.z(), GL_RGBA, GL_FLOAT);
    std::memcpy(table->data(), out.residency.pageTable.data(), out.residency.pageTable.size() * sizeof(float));
    table->setInternalTextureFormat(GL_RGBA32F_ARB);
    out.pageTable = makeTexture3D(table.get(), GL_RGBA32F_ARB, osg::Texture::NEAREST);
    return out;
}

}  // namespace volren
