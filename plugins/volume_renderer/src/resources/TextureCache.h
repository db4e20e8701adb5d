#pragma once
// Internal to the pass: the volume textures and transfer-function tables of a VolumeScene.
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <osg/Texture1D>
#include <osg/Texture3D>

#include <volume_renderer/BrickPool.h>
#include <volume_renderer/BrickStreamer.h>
#include <volume_renderer/MacrocellGrid.h>

#include "BuiltVolumes.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

namespace volren {

/// GL textures made from model objects, remade when their modified count changes and freed
/// when no cull traversal used them for a few frames. One texture per Volume (and filter) and
/// per TransferFunction (and table kind), however many nodes show it.
class TextureCache
{
public:
    /// The 3D texture of `volume` (nearest-voxel filtering when `nearest`; mip level `level` of it,
    /// a texture of its own; 8-bit data as 16-bit texels when `wide`), used in cull `cull`.
    osg::Texture* volume(const Volume& volume, bool nearest, unsigned int cull, int level = 0, bool wide = false);
    /// The 1D table of `transfer` (associated colours when `premultiplied`), used in cull `cull`.
    osg::Texture* table(const TransferFunction& transfer, bool premultiplied, unsigned int cull);
    /// What decides a cell's occupancy texel under one classification (MacrocellGrid.h's occupancyOf).
    using CellTest = std::function<bool(double lo, double hi)>;
    /// The occupancy texture of `volume` in macrocells of `cellSize` voxels with `apron` under the
    /// predicates `tests` makes (visibility; and homogeneity, or none), remade when the volume,
    /// `transfer` or `key` (the classification, its settings, the tolerance) changes; the
    /// value-range grid is kept per volume. `anyVisible` tells whether some cell may be visible.
    osg::Texture* occupancy(const Volume& volume, const TransferFunction& transfer, int cellSize, int apron,
                            const std::string& key, const std::function<std::pair<CellTest, CellTest>()>& tests,
                            unsigned int cull, bool& anyVisible);
    /// The value-range texture of `volume` in macrocells of `cellSize` voxels with `apron`.
    osg::Texture* ranges(const Volume& volume, int cellSize, int apron, unsigned int cull);
    /// `volume` (a lazy volume: its full-resolution source) from mip level `level` down in bricks
    /// of `brickSize` within `budget` bytes and textures of at most `largest` texels per axis
    /// (8-bit data in 16-bit texels when `wide`), planned for the view `textureToClip` when given,
    /// leaving out the bricks `hiding` says the transfer function hides.
    const BrickedVolume& bricked(const Volume& volume, int level, int brickSize, std::size_t budget, int largest, bool wide,
                                 const std::optional<osg::Matrixd>& textureToClip, const BrickHidingRule* hiding,
                                 unsigned int cull);
    /// How bricked volumes fill: at most `uploadBytesPerFrame` a frame (0: no limit), and whether
    /// every frame waits for its bricks (`complete`, offline) or draws what is there (streaming).
    void setBrickStreaming(std::size_t uploadBytesPerFrame, bool complete);
    /// Statistics of the bricked volumes used in cull `cull`.
    std::vector<BrickStatistics> brickStatistics(unsigned int cull) const;
    /// Bricks the bricked volumes used in cull `cull` still wait for (streaming).
    std::size_t pendingBricks(unsigned int cull) const;
    /// Waits up to `seconds` for the loaders of the bricked volumes used in cull `cull`.
    void waitForBricks(unsigned int cull, double seconds) const;
    /// Occupancy grids built so far (each TF or classification change builds one).
    unsigned int occupancyBuilds() const { return _occupancyBuilds; }
    /// The auxiliary volumes built on the GPU (light volumes, opacity mip chains), per node.
    BuiltVolumes& builtVolumes() { return _builtVolumes; }
    const BuiltVolumes& builtVolumes() const { return _builtVolumes; }
    /// Frees what the last few cull traversals before `cull` did not use.
    void endCull(unsigned int cull);
    /// Textures held.
    std::size_t count() const;
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
    std::map<std::tuple<const Volume*, bool, int, bool>, Entry<Volume, osg::Texture3D>> _volumes;
    /// The coarser levels' images of a volume (VolumeMipChain.h), kept longer than their textures
    /// so that switching levels (volren view while dragging) uploads and does not rebuild.
    struct Levels
    {
        std::vector<osg::ref_ptr<osg::Image>> images;  ///< levels 1, 2, ...
        unsigned int modified = 0;
        unsigned int lastCull = 0;
    };
    std::map<const Volume*, Levels> _levels;
    std::map<std::pair<const TransferFunction*, bool>, Entry<TransferFunction, osg::Texture1D>> _tables;
    struct Ranges
    {
        MacrocellGrid grid;
        osg::ref_ptr<osg::Texture3D> texture;  ///< made on the first ranges() call
        unsigned int modified = 0;
        unsigned int lastCull = 0;
    };
    std::map<std::tuple<const Volume*, int, int>, Ranges> _ranges;
    /// The grid of `volume`, (re)built when missing or the volume changed.
    Ranges& rangesOf(const Volume& volume, int cellSize, int apron, unsigned int cull, bool& rebuilt);
    struct Occupancy
    {
        osg::ref_ptr<const Volume> volume;
        osg::ref_ptr<const TransferFunction> transfer;
        osg::ref_ptr<osg::Texture3D> texture;
        bool anyVisible = true;  ///< some cell may be visible
        unsigned int volumeModified = 0, transferModified = 0;
        unsigned int lastCull = 0;
    };
    std::map<std::tuple<const Volume*, const TransferFunction*, int, int, std::string>, Occupancy> _occupancies;
    struct Bricks
    {
        osg::ref_ptr<const Volume> volume;
        osg::ref_ptr<BrickStreamer> streamer;
        unsigned int modified = 0;
        unsigned int lastCull = 0;
    };
    std::map<std::tuple<const Volume*, int, std::size_t, int, bool>, Bricks> _bricks;
    std::size_t _uploadBytesPerFrame = 0;
    bool _completeBricks = true;
    /// Levels 1 .. `count` of `volume`'s mip chain, made when missing or the volume changed.
    const std::vector<osg::ref_ptr<osg::Image>>& levelImages(const Volume& volume, int count, unsigned int cull);
    unsigned int _occupancyBuilds = 0;
    BuiltVolumes _builtVolumes;
};

}  // namespace volren
