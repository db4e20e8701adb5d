// A bricked volume's pool kept filled by loader threads (BrickStreamer.h).
#include <volume_renderer/BrickStreamer.h>

#include <volume_renderer/VolumeTextures.h>

#include "BrickPoolTexture.h"

#include <osg/Notify>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace volren {

BrickStreamer::BrickStreamer(BrickSourceLevels source, const BrickBudget& budget)
    : _source(std::move(source)), _budget(budget), _mirror(std::make_shared<BrickPoolMirror>())
{
    _state.layout = brickLayout(_source.levelDims, budget.brickSize);
    const BrickLayout& layout = _state.layout;
    if (layout.levels.size() > 16) throw std::invalid_argument("a volume of more than 16 levels cannot be bricked");
    _texels = budget.brickSize + 2;
    const std::size_t voxelBytes = voxelSize(_source.type);
    _slotBytes = std::size_t(_texels) * _texels * _texels * voxelBytes;
    const std::size_t gpuSlotBytes = _slotBytes / voxelBytes * (budget.wide && voxelBytes == 1 ? 2 : voxelBytes);
    // As many slots as the budget holds, no more than every level's bricks need.
    std::size_t needed = 0;
    for (std::size_t level = 0; level < layout.levels.size(); ++level) {
        const MacrocellGrid* g = level < _source.ranges.size() && _source.ranges[level].size() ? &_source.ranges[level] : nullptr;
        if (!g || !_source.constantBricks) {
            needed += layout.brickCount(int(level));
            continue;
        }
        for (std::size_t i = 0; i < g->size(); ++i) needed += !(g->lo[i] == g->hi[i] || g->lo[i] > g->hi[i]);
    }
    _byBudget = budget.bytes / gpuSlotBytes;
    _maxCapacity = std::min(_byBudget, std::max<std::size_t>(needed, 1));
    _maxCapacity = std::min(_maxCapacity, slotsWithin(_maxCapacity));
    planBricks(layout, _source.ranges, 0, _maxCapacity, _source.constantBricks);  // throws when the coarsest level does not fit
    _mirror->slotBytes = _slotBytes;
    _mirror->slotTexels = _texels;
    _mirror->pixelType = pixelTypeFor(_source.type);
    _format = volumeTextureFormat(_source.type, budget.wide);
    resizePool(std::min<std::size_t>(_maxCapacity, 64));  // grown to what plans need (GPUs allocate it whole)

    const osg::Vec3i& t = layout.tableSize;
    _table.assign(std::size_t(t.x()) * t.y() * t.z() * 4, 0.0f);
    osg::ref_ptr<osg::Image> table = new osg::Image;
    table->setImage(t.x(), t.y(), t.z(), GL_RGBA32F_ARB, GL_RGBA, GL_FLOAT, reinterpret_cast<unsigned char*>(_table.data()),
                    osg::Image::NO_DELETE, 1);
    _state.pageTable = makeTexture3D(table.get(), GL_RGBA32F_ARB, osg::Texture::NEAREST);

    const unsigned int threads = std::clamp(std::thread::hardware_concurrency(), 1u, 2u);
    for (unsigned int i = 0; i < threads; ++i) _threads.emplace_back([this] { loaderLoop(); });
}

std::size_t BrickStreamer::slotsWithin(std::size_t wanted) const
{
    const osg::Vec3i slots = poolBoxFor(wanted);
    return std::size_t(slots.x()) * slots.y() * slots.z();
}

osg::Vec3i BrickStreamer::poolBoxFor(std::size_t wanted) const
{
    osg::Vec3i slots = poolSlotsFor(std::max<std::size_t>(1, wanted), _texels, _budget.maxTextureSize);
    // Rounded up to a box of slots, the pool may pass the budget: fewer layers (or rows) then.
    const std::size_t perAxis = std::size_t(std::max(1, _budget.maxTextureSize / _texels));
    if (std::size_t(slots.x()) * slots.y() * slots.z() > _byBudget && _byBudget > 0 && _byBudget <= perAxis)
        return osg::Vec3i(int(_byBudget), 1, 1);  // a few slots: one row holds exactly the budget's
    if (std::size_t(slots.x()) * slots.y() * slots.z() > _byBudget && _byBudget > 0) {
        const std::size_t layer = std::size_t(slots.x()) * slots.y();
        if (_byBudget >= layer) {
            slots.z() = int(_byBudget / layer);
        } else {
            slots.z() = 1;
            slots.y() = std::max(1, int(_byBudget / std::size_t(slots.x())));
            if (std::size_t(slots.x()) > _byBudget) slots.x() = int(_byBudget), slots.y() = 1;
        }
    }
    return slots;
}

void BrickStreamer::resizePool(std::size_t wanted)
{
    const osg::Vec3i slots = poolBoxFor(std::min(wanted, _maxCapacity));
    const std::size_t capacity = std::min(_maxCapacity, std::size_t(slots.x()) * slots.y() * slots.z());
    {
        std::lock_guard<std::mutex> lock(_mirror->mutex);
        std::unique_ptr<std::uint8_t[]> texels(new std::uint8_t[capacity * _slotBytes]);  // uninitialised: RAM for slots written only
        for (std::size_t s = 0; s < std::min(capacity, _capacity); ++s)
            if (_mirror->used[s]) std::memcpy(texels.get() + s * _slotBytes, _mirror->texels.get() + s * _slotBytes, _slotBytes);
        _mirror->texels = std::move(texels);
        _mirror->used.resize(capacity, false);
        _mirror->slots = slots;
        _mirror->changes.clear();
        _mirror->uploaded.clear();  // a new texture: every context loads it whole
    }
    _capacity = capacity;
    _slots.resize(capacity, std::nullopt);
    _slotUsed.resize(capacity, 0);
    _state.poolTexels = slots * _texels;
    _state.pool = makeBrickPoolTexture(_mirror, _state.poolTexels, _format);
    // Slots keep their numbers; their places in the new box move.
    for (const auto& [id, slot] : _slotOf)
        if (!_hidden.count(id)) setSlotEntry(id, slot);
}

BrickStreamer::~BrickStreamer()
{
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _stop = true;
    }
    _work.notify_all();
    for (std::thread& t : _threads) t.join();
}

void BrickStreamer::setStreaming(std::size_t uploadBytesPerFrame, bool complete)
{
    _budget.uploadBytesPerFrame = uploadBytesPerFrame;
    _budget.complete = complete;
}

void BrickStreamer::setEntry(const BrickId& id, float x, float y, float z, PageEntry kind)
{
    const BrickLayout& layout = _state.layout;
    const osg::Vec3i& t = layout.tableSize;
    float* e = &_table[((std::size_t(id.brick.z() + layout.levels[std::size_t(id.level)].tableZ) * t.y() + id.brick.y()) *
                            t.x() + id.brick.x()) * 4];
    e[0] = x;
    e[1] = y;
    e[2] = z;
    e[3] = float(kind);
    _tableDirty = true;
}

void BrickStreamer::setSlotEntry(const BrickId& id, int slot)
{
    const osg::Vec3i& n = _mirror->slots;
    setEntry(id, float(slot % n.x()), float(slot / n.x() % n.y()), float(slot / (n.x() * n.y())), PageEntry::Resident);
}

void BrickStreamer::replan(int firstLevel, const std::optional<osg::Matrixd>& textureToClip, const BrickHidingRule* hiding)
{
    // Bricks the last TF hid read from their level again until the new plan says otherwise.
    for (const BrickId& id : _hidden) {
        if (auto it = _slotOf.find(id); it != _slotOf.end())
            setSlotEntry(id, it->second);  // still in its slot from before the TF hid it
        else
            setEntry(id, 0.0f, 0.0f, 0.0f, PageEntry::Missing);
    }
    _hidden.clear();
    BrickHiding hidden;
    if (hiding && _source.rangesWithApron) {
        std::vector<MacrocellGrid>& grids = _apronRanges[hiding->apron];
        if (grids.empty())
            for (int level = 0; level < int(_state.layout.levels.size()); ++level)
                grids.push_back(_source.rangesWithApron(level, hiding->apron));
        hidden = [this, &grids, hiding](int level, const osg::Vec3i& b) -> std::optional<float> {
            const MacrocellGrid& g = grids[std::size_t(level)];
            if (!g.size() || g.cells != _state.layout.levels[std::size_t(level)].bricks) return std::nullopt;
            const std::size_t i = g.index(b.x(), b.y(), b.z());
            if (g.lo[i] > g.hi[i]) return std::nullopt;  // NaN only: left to the constant test
            if (hiding->mayShow(g.lo[i], g.hi[i])) return std::nullopt;
            _hidden.insert(BrickId{level, b});
            return g.lo[i];
        };
    }
    const BrickVisibility visible = textureToClip ? brickVisibility(_state.layout, *textureToClip) : BrickVisibility{};
    _plan = planBricks(_state.layout, _source.ranges, firstLevel, _maxCapacity, _source.constantBricks, visible, hidden);
    if (_plan.slotted.size() > _capacity) resizePool(_plan.slotted.size() + _plan.slotted.size() / 4);
    _plannedLevel = firstLevel;
    _plannedView = textureToClip;
    _plannedHiding = hiding ? hiding->key : std::string();
    ++_planCount;
    for (const auto& [id, value] : _plan.constant) setEntry(id, value, 0.0f, 0.0f, PageEntry::Constant);
    _wanted.clear();
    std::vector<BrickId> toLoad;
    for (const BrickId& id : _plan.slotted) {
        if (_constantFound.count(id)) continue;
        _wanted[id] = true;
        if (auto it = _slotOf.find(id); it != _slotOf.end()) {
            _slotUsed[std::size_t(it->second)] = _planCount;
            continue;
        }
        toLoad.push_back(id);
    }
    {
        std::lock_guard<std::mutex> lock(_mutex);
        for (const BrickId& id : _queue) _requested.erase(id);
        _queue.clear();
        for (const BrickId& id : toLoad)
            if (_requested.emplace(id, true).second) _queue.push_back(id);
    }
    _work.notify_all();
}

void BrickStreamer::take(std::vector<Loaded>& done, const std::set<BrickId>& exempt)
{
    std::size_t bytes = 0;
    std::vector<int> freeSlots;
    for (std::size_t s = _slots.size(); s-- > 0;)
        if (!_slots[s]) freeSlots.push_back(int(s));
    std::vector<Loaded> deferred;
    for (Loaded& l : done) {
        if (l.constant) {
            _constantFound[l.id] = l.value;
            setEntry(l.id, l.value, 0.0f, 0.0f, PageEntry::Constant);
            _wanted.erase(l.id);
            continue;
        }
        if (!_wanted.count(l.id) || _slotOf.count(l.id)) continue;  // the view moved on
        if (_budget.uploadBytesPerFrame && bytes >= _budget.uploadBytesPerFrame && !exempt.count(l.id)) {
            deferred.push_back(std::move(l));  // over this frame's upload budget: a later frame takes it
            continue;
        }
        int slot = -1;
        if (!freeSlots.empty()) {
            slot = freeSlots.back();
            freeSlots.pop_back();
        } else {  // the least recently wanted brick the plan no longer wants
            unsigned long long oldest = _planCount;
            for (std::size_t s = 0; s < _slots.size(); ++s)
                if (_slotUsed[s] < oldest) {
                    oldest = _slotUsed[s];
                    slot = int(s);
                }
            if (slot < 0) {  // every slot is wanted (the plan fits the pool, so only briefly)
                deferred.push_back(std::move(l));
                continue;
            }
            const BrickId old = *_slots[std::size_t(slot)];
            if (!_hidden.count(old) && !_constantFound.count(old)) setEntry(old, 0.0f, 0.0f, 0.0f, PageEntry::Missing);
            _slotOf.erase(old);
            ++_evicted;
        }
        _mirror->write(slot, l.texels);
        setSlotEntry(l.id, slot);
        _slots[std::size_t(slot)] = l.id;
        _slotUsed[std::size_t(slot)] = _planCount;
        _slotOf[l.id] = slot;
        if (!exempt.count(l.id)) bytes += _slotBytes;
        ++_uploaded;
    }
    done.swap(deferred);
}

const BrickedVolume& BrickStreamer::update(int firstLevel, const std::optional<osg::Matrixd>& textureToClip,
                                           const BrickHidingRule* hiding)
{
    auto sameView = [&] {
        if (_plannedView.has_value() != textureToClip.has_value()) return false;
        return !textureToClip || *_plannedView == *textureToClip;
    };
    if (_plannedLevel != firstLevel || !sameView() || _plannedHiding != (hiding ? hiding->key : std::string()))
        replan(firstLevel, textureToClip, hiding);
    // A frame is complete at some level: streaming or not, it waits for the coarsest levels
    // (the first 64 bricks the plan lists, the coarsest level at least), which the upload
    // budget does not count; offline it waits for all.
    std::size_t mustHave = _budget.complete ? _plan.slotted.size() : std::min<std::size_t>(_plan.slotted.size(), 64);
    while (mustHave < _plan.slotted.size() && _plan.slotted[mustHave].level == _plan.slotted.front().level) ++mustHave;
    const std::set<BrickId> exempt(_plan.slotted.begin(), _plan.slotted.begin() + std::ptrdiff_t(mustHave));
    auto missing = [&] {
        for (const BrickId& id : exempt)
            if (_wanted.count(id) && !_slotOf.count(id)) return true;
        return false;
    };
    std::size_t deferred = 0;  // bricks put back for a later frame: waiting is for new ones
    for (bool wait = missing();; wait = missing()) {
        std::vector<Loaded> done;
        {
            std::unique_lock<std::mutex> lock(_mutex);
            if (wait) _idle.wait(lock, [&] { return _done.size() > deferred || (_queue.empty() && _busy == 0); });
            done.swap(_done);
            for (const Loaded& l : done) _requested.erase(l.id);
        }
        take(done, exempt);
        if (!done.empty()) {  // deferred: the next frame takes them
            std::lock_guard<std::mutex> lock(_mutex);
            for (const Loaded& l : done) _requested[l.id] = true;
            _done.insert(_done.begin(), std::make_move_iterator(done.begin()), std::make_move_iterator(done.end()));
        }
        deferred = done.size();
        if (!wait) break;
        std::lock_guard<std::mutex> lock(_mutex);
        if (_queue.empty() && _busy == 0 && _done.size() == deferred && missing()) break;  // nothing more will come
    }
    if (_tableDirty) {
        _state.pageTable->getImage()->dirty();
        _tableDirty = false;
    }
    _state.firstLevel = _plan.firstLevel;
    _state.levelSampled = _plan.finest;
    return _state;
}

std::size_t BrickStreamer::pending() const
{
    std::size_t n = 0;
    for (const auto& [id, wanted] : _wanted) n += !_slotOf.count(id);
    return n;
}

void BrickStreamer::waitForLoads(double seconds) const
{
    std::unique_lock<std::mutex> lock(_mutex);
    _idle.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return _queue.empty() && _busy == 0; });
}

BrickStatistics BrickStreamer::statistics(const std::string& volume) const
{
    BrickStatistics s{.volume = volume,
                      .levelSampled = _plan.finest,
                      .resident = _slotOf.size(),
                      .constant = _plan.constant.size() + _constantFound.size(),
                      .hidden = _hidden.size(),
                      .pending = pending(),
                      .poolBytes = std::size_t(_state.poolTexels.x()) * _state.poolTexels.y() * _state.poolTexels.z() *
                                   (_state.pool->getInternalFormat() == GL_R16 || _state.pool->getInternalFormat() == GL_R16_SNORM ? 2
                                                                                                    : voxelSize(_source.type)),
                      .budgetBytes = _budget.bytes,
                      .sourceBytes = _source.hostBytes ? _source.hostBytes() : 0};
    for (int level = _plan.firstLevel; level < _plan.finest; ++level) s.missing += _state.layout.brickCount(level);
    {
        std::lock_guard<std::mutex> lock(_mutex);
        s.loaded = _loaded;
    }
    s.uploaded = _uploaded;
    s.evicted = _evicted;
    return s;
}

}  // namespace volren
