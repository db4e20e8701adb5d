#include "TextureCache.h"

#include <volume_renderer/VolumeTextures.h>

namespace volren {

namespace {

/// Whether an entry last used in `last` is stale in cull `cull`.
bool stale(unsigned int last, unsigned int cull)
{
    return cull - last > 2;
}

template <typename Map>
void dropStale(Map& map, unsigned int cull)
{
    for (auto it = map.begin(); it != map.end();) it = stale(it->second.lastCull, cull) ? map.erase(it) : std::next(it);
}

template <typename Map>
std::size_t imageBytes(const Map& map)
{
    std::size_t bytes = 0;
    for (const auto& [key, entry] : map)
        if (const osg::Image* image = entry.texture->getImage()) bytes += image->getTotalSizeInBytesIncludingMipmaps();
    return bytes;
}

}  // namespace

osg::Texture* TextureCache::volume(const Volume& volume, bool nearest, unsigned int cull, bool mipmapped, bool wide)
{
    auto& gl = _volumes[{&volume, nearest, mipmapped, wide}];
    if (!gl.texture || gl.modified != volume.modifiedCount()) {
        gl.source = &volume;
        gl.texture = makeVolumeTexture(volume, mipmapped, wide);
        if (nearest) {
            gl.texture->setFilter(osg::Texture::MIN_FILTER,
                                  mipmapped ? osg::Texture::NEAREST_MIPMAP_NEAREST : osg::Texture::NEAREST);
            gl.texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
        }
        gl.modified = volume.modifiedCount();
    }
    gl.lastCull = cull;
    return gl.texture.get();
}

osg::Texture* TextureCache::table(const TransferFunction& transfer, bool premultiplied, unsigned int cull)
{
    auto& gl = _tables[{&transfer, premultiplied}];
    if (!gl.texture || gl.modified != transfer.modifiedCount()) {
        gl.source = &transfer;
        gl.texture = makeTransferFunctionTexture(transfer, premultiplied);
        gl.modified = transfer.modifiedCount();
    }
    gl.lastCull = cull;
    return gl.texture.get();
}

osg::Texture* TextureCache::occupancy(const Volume& volume, const TransferFunction& transfer, int cellSize, int apron,
                                      const std::string& key, const std::function<std::pair<CellTest, CellTest>()>& tests,
                                      unsigned int cull)
{
    bool newRanges = false;
    const Ranges& ranges = rangesOf(volume, cellSize, apron, cull, newRanges);
    Occupancy& o = _occupancies[{&volume, &transfer, cellSize, apron, key}];
    if (!o.texture || newRanges || o.volumeModified != volume.modifiedCount() ||
        o.transferModified != transfer.modifiedCount()) {
        o.volume = &volume;
        o.transfer = &transfer;
        const auto [visible, homogeneous] = tests();
        o.texture = makeOccupancyTexture(ranges.grid, occupancyOf(ranges.grid, visible, homogeneous));
        o.volumeModified = volume.modifiedCount();
        o.transferModified = transfer.modifiedCount();
        ++_occupancyBuilds;
    }
    o.lastCull = cull;
    return o.texture.get();
}

TextureCache::Ranges& TextureCache::rangesOf(const Volume& volume, int cellSize, int apron, unsigned int cull,
                                             bool& rebuilt)
{
    Ranges& ranges = _ranges[{&volume, cellSize, apron}];
    rebuilt = ranges.grid.size() == 0 || ranges.modified != volume.modifiedCount();
    if (rebuilt) {
        ranges.grid = buildMacrocellGrid(volume, cellSize, apron);
        ranges.texture = nullptr;
        ranges.modified = volume.modifiedCount();
    }
    ranges.lastCull = cull;
    return ranges;
}

osg::Texture* TextureCache::ranges(const Volume& volume, int cellSize, int apron, unsigned int cull)
{
    bool rebuilt = false;
    Ranges& ranges = rangesOf(volume, cellSize, apron, cull, rebuilt);
    if (!ranges.texture) ranges.texture = makeRangeTexture(ranges.grid);
    return ranges.texture.get();
}

void TextureCache::endCull(unsigned int cull)
{
    dropStale(_volumes, cull);
    dropStale(_tables, cull);
    dropStale(_ranges, cull);
    dropStale(_occupancies, cull);
}

std::size_t TextureCache::count() const
{
    std::size_t rangeTextures = 0;
    for (const auto& [key, r] : _ranges) rangeTextures += r.texture ? 1 : 0;
    return _volumes.size() + _tables.size() + _occupancies.size() + rangeTextures;
}

std::size_t TextureCache::bytes() const
{
    std::size_t occupancy = 0;
    for (const auto& [key, o] : _occupancies) occupancy += o.texture->getImage()->getTotalSizeInBytes();
    for (const auto& [key, r] : _ranges)
        if (r.texture) occupancy += r.texture->getImage()->getTotalSizeInBytes();
    return imageBytes(_volumes) + imageBytes(_tables) + occupancy;
}

}  // namespace volren
