#pragma once
// Internal to BrickStreamer: the brick pool's texture and the RAM mirror its subload callback
// uploads from, so every GL context (a second viewer too) gets every brick.
#include <osg/GL>
#include <osg/State>
#include <osg/Texture3D>
#include <osg/Vec3i>

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace volren {

/// The pool's texels in RAM (slot after slot) and which slots each GL context has yet to
/// receive: a context made later (a second viewer) or that missed trimmed changes gets them all.
struct BrickPoolMirror
{
    std::mutex mutex;
    /// Uninitialised, so RAM is taken only by the slots written (the pool is sized for the
    /// budget, the plan may use a fraction of it).
    std::unique_ptr<std::uint8_t[]> texels;
    std::size_t slotBytes = 0;
    int slotTexels = 0;
    osg::Vec3i slots;
    GLenum pixelType = GL_UNSIGNED_BYTE;
    std::vector<bool> used;
    unsigned long long sequence = 0;                        ///< changes so far
    std::deque<std::pair<unsigned long long, int>> changes;  ///< (sequence, slot), oldest first
    std::map<unsigned int, unsigned long long> uploaded;   ///< per context: the last change it has

    /// Copies `data` (one slot of stored voxels) into slot `slot` and logs the change.
    void write(int slot, const std::vector<std::uint8_t>& data);
    /// Sends the current context what it lacks (`all`: every slot in use) with glTexSubImage3D.
    void upload(osg::State& state, bool all);
};

/// A pool texture of `texels` in `format`, allocated per context on first use and fed from
/// `mirror` (linear filtering, clamped edges).
osg::ref_ptr<osg::Texture3D> makeBrickPoolTexture(std::shared_ptr<BrickPoolMirror> mirror, const osg::Vec3i& texels,
                                                  GLenum format);

}  // namespace volren
