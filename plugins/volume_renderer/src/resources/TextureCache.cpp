#include "TextureCache.h"

#include <volume_renderer/VolumeMipChain.h>
#include <volume_renderer/VolumeTextures.h>

#include <algorithm>
#include <cstring>

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

/// Bytes per texel of the internal formats volren's textures use (their images may hold
/// narrower data: 8-bit voxels in a 16-bit texture).
std::size_t texelBytes(GLint format)
{
    switch (format) {
    case GL_R8: case GL_R8_SNORM: return 1;
    case GL_R16: case GL_R16_SNORM: return 2;
    case GL_R32F: case GL_RG16F: return 4;
    case GL_RGBA32F_ARB: return 16;
    default: return 0;
    }
}

/// GPU storage of a texture made from an image: its texels (all mip levels) in the internal
/// format; the image's own size where the format is not one of the above.
std::size_t textureBytes(const osg::Texture& texture)
{
    const osg::Image* image = texture.getImage(0);
    if (!image) return 0;
    const std::size_t perTexel = texelBytes(texture.getInternalFormat());
    const std::size_t imageTexels = std::size_t(image->s()) * image->t() * image->r();
    if (perTexel == 0 || imageTexels == 0) return image->getTotalSizeInBytesIncludingMipmaps();
    // The image's bytes per texel scale to the texture's, level by level alike.
    return image->getTotalSizeInBytesIncludingMipmaps() / (image->getTotalSizeInBytes() / imageTexels) * perTexel;
}

template <typename Map>
std::size_t imageBytes(const Map& map)
{
    std::size_t bytes = 0;
    for (const auto& [key, entry] : map) bytes += textureBytes(*entry.texture);
    return bytes;
}

}  // namespace

osg::Texture* TextureCache::volume(const Volume& volume, bool nearest, unsigned int cull, int level, bool wide)
{
    auto& gl = _volumes[{&volume, nearest, level, wide}];
    if (!gl.texture || gl.modified != volume.modifiedCount()) {
        gl.source = &volume;
        osg::Image* image = nullptr;
        if (level > 0) {
            const auto& images = levelImages(volume, level, cull);
            image = images.at(std::size_t(std::min<int>(level, int(images.size())) - 1)).get();
        }
        gl.texture = makeVolumeTexture(volume, wide, image);
        if (nearest) {
            gl.texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
            gl.texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
        }
        gl.modified = volume.modifiedCount();
    }
    if (level > 0) _levels[&volume].lastCull = cull;
    gl.lastCull = cull;
    return gl.texture.get();
}

const std::vector<osg::ref_ptr<osg::Image>>& TextureCache::levelImages(const Volume& volume, int count, unsigned int cull)
{
    Levels& levels = _levels[&volume];
    if (levels.modified != volume.modifiedCount() || int(levels.images.size()) < count) {
        levels.images = mipLevelImages(volume, count);
        levels.modified = volume.modifiedCount();
    }
    levels.lastCull = cull;
    return levels.images;
}

namespace {

/// Where a bricked volume's voxels come from: a lazy volume's source, or the volume and its
/// mip chain in memory (`images`: levels 1, 2, ...).
BrickSourceLevels sourceLevels(const Volume& volume, const std::vector<osg::ref_ptr<osg::Image>>& images, int brickSize)
{
    BrickSourceLevels s;
    s.type = volume.type();
    // The ranges leave NaN voxels out, so a brick with some would pass for constant: with
    // non-finite voxels every brick is kept.
    s.constantBricks = volume.nonFiniteCount() == 0;
    const std::size_t bytes = voxelSize(volume.type());
    if (const BrickSource* lazy = volume.fullResolution()) {
        for (int level = 0; level < lazy->levelCount(); ++level) s.levelDims.push_back(lazy->levelDims(level));
        s.read = [lazy](int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) {
            lazy->read(level, origin, size, out);
        };
        s.hostBytes = [lazy] { return lazy->residentBytes(); };
        s.keep = lazy;
        // The level held in memory has known ranges; the others are learnt as bricks are read.
        s.ranges.resize(s.levelDims.size());
        const int preview = volume.fullResolutionLevel();
        s.ranges[std::size_t(preview)] = buildMacrocellGrid(volume, brickSize, 1);
        s.rangesWithApron = [v = osg::ref_ptr<const Volume>(&volume), preview, brickSize](int level, int apron) {
            return level == preview ? buildMacrocellGrid(*v, brickSize, apron) : MacrocellGrid{};
        };
        return s;
    }
    std::vector<const std::uint8_t*> data{volume.data()};
    s.levelDims.push_back(volume.dims());
    for (const osg::ref_ptr<osg::Image>& image : images) {
        data.push_back(image->data());
        s.levelDims.emplace_back(image->s(), image->t(), image->r());
    }
    // A level as a Volume of its own, for its ranges (level 0: the volume itself).
    auto levelVolume = [v = osg::ref_ptr<const Volume>(&volume), images, data, dims = s.levelDims, bytes](int level) {
        if (level == 0) return v;
        osg::ref_ptr<Volume> copy = new Volume;
        const osg::Vec3i& d = dims[std::size_t(level)];
        const std::uint8_t* begin = data[std::size_t(level)];
        copy->assign(v->type(), d, std::vector<std::uint8_t>(begin, begin + std::size_t(d.x()) * d.y() * d.z() * bytes));
        return osg::ref_ptr<const Volume>(copy);
    };
    for (int level = 0; level < int(s.levelDims.size()); ++level) s.ranges.push_back(buildMacrocellGrid(*levelVolume(level), brickSize, 1));
    s.rangesWithApron = [levelVolume, brickSize](int level, int apron) {
        return buildMacrocellGrid(*levelVolume(level), brickSize, apron);
    };
    s.read = [data, dims = s.levelDims, bytes](int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out) {
        const osg::Vec3i& d = dims[std::size_t(level)];
        for (int z = 0; z < size.z(); ++z)
            for (int y = 0; y < size.y(); ++y)
                std::memcpy(out + (std::size_t(z) * size.y() + y) * size.x() * bytes,
                            data[std::size_t(level)] +
                                ((std::size_t(origin.z() + z) * d.y() + std::size_t(origin.y() + y)) * d.x() + origin.x()) * bytes,
                            std::size_t(size.x()) * bytes);
    };
    return s;
}

}  // namespace

const BrickedVolume& TextureCache::bricked(const Volume& volume, int level, int brickSize, std::size_t budget, int largest,
                                           bool wide, const std::optional<osg::Matrixd>& textureToClip,
                                           const BrickHidingRule* hiding, unsigned int cull)
{
    Bricks& b = _bricks[{&volume, brickSize, budget, largest, wide}];
    if (!b.streamer || b.modified != volume.modifiedCount()) {
        b.volume = &volume;
        b.streamer = nullptr;  // its loaders stop before the new one reads
        const auto& images = volume.fullResolution() ? std::vector<osg::ref_ptr<osg::Image>>{}
                                                     : levelImages(volume, mipLevelCount(volume.dims()) - 1, cull);
        BrickSourceLevels source = sourceLevels(volume, images, brickSize);
        source.keep = source.keep ? source.keep : osg::ref_ptr<const osg::Referenced>(&volume);
        b.streamer = new BrickStreamer(std::move(source), BrickBudget{.brickSize = brickSize,
                                                                      .bytes = budget,
                                                                      .maxTextureSize = largest,
                                                                      .wide = wide,
                                                                      .uploadBytesPerFrame = _uploadBytesPerFrame,
                                                                      .complete = _completeBricks});
        b.modified = volume.modifiedCount();
    }
    b.streamer->setStreaming(_uploadBytesPerFrame, _completeBricks);
    b.lastCull = cull;
    return b.streamer->update(level, textureToClip, hiding);
}

void TextureCache::setBrickStreaming(std::size_t uploadBytesPerFrame, bool complete)
{
    _uploadBytesPerFrame = uploadBytesPerFrame;
    _completeBricks = complete;
}

std::vector<BrickStatistics> TextureCache::brickStatistics(unsigned int cull) const
{
    std::vector<BrickStatistics> out;
    for (const auto& [key, b] : _bricks)
        if (b.lastCull == cull) out.push_back(b.streamer->statistics(b.volume->getName()));
    return out;
}

std::size_t TextureCache::pendingBricks(unsigned int cull) const
{
    std::size_t n = 0;
    for (const auto& [key, b] : _bricks)
        if (b.lastCull == cull) n += b.streamer->pending();
    return n;
}

void TextureCache::waitForBricks(unsigned int cull, double seconds) const
{
    for (const auto& [key, b] : _bricks)
        if (b.lastCull == cull) b.streamer->waitForLoads(seconds);
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
                                      unsigned int cull, bool& anyVisible)
{
    bool newRanges = false;
    const Ranges& ranges = rangesOf(volume, cellSize, apron, cull, newRanges);
    Occupancy& o = _occupancies[{&volume, &transfer, cellSize, apron, key}];
    if (!o.texture || newRanges || o.volumeModified != volume.modifiedCount() ||
        o.transferModified != transfer.modifiedCount()) {
        o.volume = &volume;
        o.transfer = &transfer;
        const auto [visible, homogeneous] = tests();
        const std::vector<std::uint8_t> cells = occupancyOf(ranges.grid, visible, homogeneous);
        o.anyVisible = std::any_of(cells.begin(), cells.end(), [](std::uint8_t c) { return c != 0; });
        o.texture = makeOccupancyTexture(ranges.grid, cells);
        o.volumeModified = volume.modifiedCount();
        o.transferModified = transfer.modifiedCount();
        ++_occupancyBuilds;
    }
    o.lastCull = cull;
    anyVisible = o.anyVisible;
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
    for (auto it = _levels.begin(); it != _levels.end();)  // kept for a few hundred frames
        it = cull - it->second.lastCull > 300 ? _levels.erase(it) : std::next(it);
    dropStale(_tables, cull);
    dropStale(_ranges, cull);
    dropStale(_occupancies, cull);
    dropStale(_bricks, cull);
    _builtVolumes.endCull(cull);
}

std::size_t TextureCache::count() const
{
    std::size_t rangeTextures = 0;
    for (const auto& [key, r] : _ranges) rangeTextures += r.texture ? 1 : 0;
    return _volumes.size() + _tables.size() + _occupancies.size() + rangeTextures + 2 * _bricks.size() +
           _builtVolumes.count();
}

std::size_t TextureCache::bytes() const
{
    std::size_t occupancy = 0;
    for (const auto& [key, o] : _occupancies) occupancy += textureBytes(*o.texture);
    for (const auto& [key, r] : _ranges)
        if (r.texture) occupancy += textureBytes(*r.texture);
    std::size_t bricks = 0;
    for (const auto& [key, b] : _bricks) {
        const BrickStatistics s = b.streamer->statistics({});
        bricks += s.poolBytes + textureBytes(*b.streamer->state().pageTable);
    }
    return imageBytes(_volumes) + imageBytes(_tables) + occupancy + bricks + _builtVolumes.bytes();
}

}  // namespace volren
