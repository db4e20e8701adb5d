#pragma once
// Keeps a bricked volume's pool filled with the bricks its frames want (VolumeStorage/bricked):
// plans per frame from the view and the budget, reads bricks on loader threads (from memory or
// a lazy volume's file), uploads them within a per-frame budget, evicts what the view left.
#include <volume_renderer/BrickPool.h>

#include <osg/Matrixd>
#include <osg/Referenced>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace volren {

struct BrickPoolMirror;  // the pool's texels in RAM (src/resources/BrickPoolTexture.h)

/// Where a bricked volume's voxels come from.
struct BrickSourceLevels
{
    std::vector<osg::Vec3i> levelDims;  ///< finest first, every level covering the same box
    VoxelType type = VoxelType::UInt8;  ///< stored type of every level
    /// Reads [origin, origin + size) of `level` (inside it), x fastest, stored values; thread-safe.
    std::function<void(int level, const osg::Vec3i& origin, const osg::Vec3i& size, std::uint8_t* out)> read;
    /// Texel ranges of each level's bricks with their border (empty where unknown until read).
    std::vector<MacrocellGrid> ranges;
    /// Texel ranges of a level's bricks with `apron` voxels around them (an empty grid where
    /// unknown), for the bricks a transfer function hides.
    std::function<MacrocellGrid(int level, int apron)> rangesWithApron;
    bool constantBricks = true;              ///< bricks of one value take no slot (false with NaN voxels)
    std::function<std::size_t()> hostBytes;  ///< RAM the source holds (a lazy file's levels), or empty
    osg::ref_ptr<const osg::Referenced> keep;  ///< what `read` reads from, kept alive
};

/// How large the pool may be and how it fills.
struct BrickBudget
{
    int brickSize = 32;               ///< brick edge in voxels (the pool slot adds a one-voxel border)
    std::size_t bytes = 0;            ///< GPU bytes the pool may take
    int maxTextureSize = 2048;        ///< largest 3D texture edge
    bool wide = false;                ///< 8-bit data in 16-bit texels
    std::size_t uploadBytesPerFrame = 0;  ///< bricks uploaded per frame at most (0: no limit)
    bool complete = true;             ///< every frame waits until its plan is resident (offline, deterministic)
};

/// Which bricks a frame's transfer function hides: those whose values, with `apron` voxels around
/// them (the Reconstruction's footprint and the gradient's one voxel), `mayShow` rejects. Such a
/// brick takes no slot; its page entry holds its lowest value, which the TF hides too.
struct BrickHidingRule
{
    int apron = 1;
    std::string key;  ///< what mayShow depends on (classification, TF and its modified count)
    std::function<bool(double lo, double hi)> mayShow;
};

/// One bricked volume's pool, page table and loader threads.
class BrickStreamer : public osg::Referenced
{
public:
    /// Sizes the pool for the bricks of every level within `budget` and starts the loaders;
    /// throws std::invalid_argument when not even the coarsest level fits.
    BrickStreamer(BrickSourceLevels source, const BrickBudget& budget);
    /// Plans the frame for the node's level `firstLevel`, with the bricks outside the view of
    /// `textureToClip` (volume texture space -> clip space) left out when given; queues loads,
    /// takes finished ones into the pool (evicting bricks the plan no longer wants) and returns
    /// what the frame binds. With budget.complete it first waits for every planned brick.
    /// With `hiding`, bricks its transfer function hides are not loaded.
    const BrickedVolume& update(int firstLevel, const std::optional<osg::Matrixd>& textureToClip,
                                const BrickHidingRule* hiding = nullptr);
    /// What the last update() returned.
    const BrickedVolume& state() const { return _state; }
    /// Planned bricks not in the pool yet.
    std::size_t pending() const;
    /// Waits up to `seconds` for the loaders to finish what is queued.
    void waitForLoads(double seconds) const;
    /// Statistics, named `volume`.
    BrickStatistics statistics(const std::string& volume) const;
    /// Changes the per-frame upload limit and whether frames wait (volren view streams).
    void setStreaming(std::size_t uploadBytesPerFrame, bool complete);

protected:
    ~BrickStreamer() override;

private:
    struct Loaded
    {
        BrickId id;
        std::vector<std::uint8_t> texels;  ///< the brick with its border, slot order
        bool constant = false;
        float value = 0.0f;  ///< the texel value of a constant brick
    };
    void loaderLoop();
    Loaded load(const BrickId& id) const;
    void setEntry(const BrickId& id, float x, float y, float z, PageEntry kind);
    void setSlotEntry(const BrickId& id, int slot);  ///< the entry of a brick resident at `slot`
    /// A box of at least `wanted` slots (fewer where the budget ends) within the largest texture.
    osg::Vec3i poolBoxFor(std::size_t wanted) const;
    std::size_t slotsWithin(std::size_t wanted) const;  ///< slots of poolBoxFor(wanted)
    /// A new pool texture of about `wanted` slots (at most _maxCapacity), keeping every slot's
    /// bricks (the mirror holds them) and moving their page entries to the new box.
    void resizePool(std::size_t wanted);
    void replan(int firstLevel, const std::optional<osg::Matrixd>& textureToClip, const BrickHidingRule* hiding);
    /// Puts loaded bricks into the pool, at most the upload budget of them besides `exempt`;
    /// leaves in `done` what waits for a later frame.
    void take(std::vector<Loaded>& done, const std::set<BrickId>& exempt);

    BrickSourceLevels _source;
    BrickBudget _budget;
    int _texels = 0;             ///< slot edge: brickSize + 2
    std::size_t _slotBytes = 0;  ///< bytes of one slot's stored voxels
    std::size_t _capacity = 0;     ///< slots of the pool now
    std::size_t _maxCapacity = 0;  ///< slots the budget (and the bricks there are) allow
    std::size_t _byBudget = 0;     ///< slots the budget holds
    GLenum _format = 0;            ///< the pool's internal format
    BrickedVolume _state;
    std::vector<float> _table;   ///< page table texels (RGBA), mirrored in _state.pageTable's image
    bool _tableDirty = false;
    std::shared_ptr<BrickPoolMirror> _mirror;  ///< the pool's texels in RAM, shared with the upload callback

    // The plan and where each brick stands.
    int _plannedLevel = -1;
    std::optional<osg::Matrixd> _plannedView;
    std::string _plannedHiding;                       ///< the hiding rule's key ("" without one)
    std::map<int, std::vector<MacrocellGrid>> _apronRanges;  ///< per apron, per level (built on first use)
    std::set<BrickId> _hidden;                        ///< bricks the plan's TF hides
    BrickPlan _plan;
    std::map<BrickId, int> _slotOf;            ///< resident bricks
    std::map<BrickId, float> _constantFound;   ///< bricks found constant when read
    std::vector<std::optional<BrickId>> _slots;  ///< per slot its brick
    std::vector<unsigned long long> _slotUsed;   ///< per slot the last plan that wanted it
    unsigned long long _planCount = 0;
    std::map<BrickId, bool> _wanted;  ///< the plan's slotted bricks

    // Loader threads.
    mutable std::mutex _mutex;
    mutable std::condition_variable _work, _idle;
    std::deque<BrickId> _queue;
    std::map<BrickId, bool> _requested;  ///< queued or being read
    std::vector<Loaded> _done;
    int _busy = 0;
    bool _stop = false;
    std::vector<std::thread> _threads;

    std::size_t _loaded = 0, _uploaded = 0, _evicted = 0;
};

}  // namespace volren
