#pragma once
// Internal to the pass: the volume textures and transfer-function tables of a VolumeScene.
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <osg/Texture1D>
#include <osg/Texture3D>

#include <map>
#include <utility>

namespace volren {

/// GL textures made from model objects, remade when their modified count changes and freed
/// when no cull traversal used them for a few frames. One texture per Volume (and filter) and
/// per TransferFunction (and table kind), however many nodes show it.
class TextureCache
{
public:
    /// The 3D texture of `volume` (nearest-voxel filtering when `nearest`), used in cull `cull`.
    osg::Texture* volume(const Volume& volume, bool nearest, unsigned int cull);
    /// The 1D table of `transfer` (associated colours when `premultiplied`), used in cull `cull`.
    osg::Texture* table(const TransferFunction& transfer, bool premultiplied, unsigned int cull);
    /// Frees what the last few cull traversals before `cull` did not use.
    void endCull(unsigned int cull);
    /// Textures held.
    std::size_t count() const { return _volumes.size() + _tables.size(); }
    /// Bytes of texture storage held.
    std::size_t bytes() const;

private:
    template <typename Source, typename Texture>
    struct Entry
    {
        osg::ref_ptr<const Source> source;  // keeps what the texture image points at alive
        osg::ref_ptr<Texture> texture;
        unsigned int modified = 0;
        unsigned int lastCull = 0;
    };
    std::map<std::pair<const Volume*, bool>, Entry<Volume, osg::Texture3D>> _volumes;
    std::map<std::pair<const TransferFunction*, bool>, Entry<TransferFunction, osg::Texture1D>> _tables;
};

}  // namespace volren
