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
        if (const osg::Image* image = entry.texture->getImage()) bytes += image->getTotalSizeInBytes();
    return bytes;
}

}  // namespace

osg::Texture* TextureCache::volume(const Volume& volume, bool nearest, unsigned int cull)
{
    auto& gl = _volumes[{&volume, nearest}];
    if (!gl.texture || gl.modified != volume.modifiedCount()) {
        gl.source = &volume;
        gl.texture = makeVolumeTexture(volume);
        if (nearest) {
            gl.texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
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

void TextureCache::endCull(unsigned int cull)
{
    dropStale(_volumes, cull);
    dropStale(_tables, cull);
}

std::size_t TextureCache::bytes() const
{
    return imageBytes(_volumes) + imageBytes(_tables);
}

}  // namespace volren
