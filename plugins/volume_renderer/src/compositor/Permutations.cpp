#include <volume_renderer/Permutations.h>
#include <volume_renderer/Slots.h>

#include <algorithm>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace volren {

namespace {

/// Lists of up to `n` implementations (multisets: order of clip shapes does not matter).
std::vector<std::vector<std::string>> multisets(const std::vector<std::string>& kinds, unsigned int n)
{
    std::vector<std::vector<std::string>> out = {{}};
    std::vector<std::vector<std::string>> frontier = {{}};
    for (unsigned int size = 1; size <= n; ++size) {
        std::vector<std::vector<std::string>> next;
        for (const auto& base : frontier)
            for (std::size_t k = 0; k < kinds.size(); ++k) {
                if (!base.empty() && kinds[k] < base.back()) continue;  // non-decreasing order
                auto grown = base;
                grown.push_back(kinds[k]);
                next.push_back(grown);
            }
        out.insert(out.end(), next.begin(), next.end());
        frontier = next;
    }
    return out;
}

std::string listText(const std::vector<std::string>& items)
{
    std::string s = "[";
    for (std::size_t i = 0; i < items.size(); ++i) s += (i ? "," : "") + items[i];
    return s + "]";
}

std::vector<std::string> parseList(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream in(text.substr(1, text.size() - 2));
    std::string item;
    while (std::getline(in, item, ','))
        if (!item.empty()) items.push_back(item);
    return items;
}

}  // namespace

PermutationSpace::PermutationSpace(const ShaderFunctionRegistry& registry, unsigned int maxInstances,
                                   unsigned int maxLights)
    : _policy(registry)
{
    // Each factor's values as text and as the implementations they name.
    std::vector<std::vector<std::vector<const ShaderFunction*>>> functions;
    for (const SlotInfo& s : slots()) {
        Factor f{s.name, {}};
        std::vector<std::vector<std::string>> lists;
        if (s.isTemplate) {
            std::vector<std::string> kinds;
            for (const std::string& name : registry.names(s.name))
                if (name != "null") kinds.push_back(name);  // no instance is the null one
            lists = multisets(kinds, maxInstances);
            for (const auto& list : lists) f.values.push_back(listText(list));
        } else {
            f.values = registry.names(s.name);  // in name order: the space's indices stay put
            for (const std::string& name : f.values) lists.push_back({name});
        }
        auto& resolved = functions.emplace_back();
        for (const auto& list : lists) {
            auto& implementations = resolved.emplace_back();
            for (const std::string& name : list) implementations.push_back(registry.find(s.name, name));
        }
        _factors.push_back(f);
    }
    Factor lights{"lights", {}};
    for (unsigned int n = 0; n <= maxLights; ++n) lights.values.push_back(std::to_string(n));
    _factors.push_back(lights);

    // Only compositions in which every slot nothing calls is null can be valid, so instead of
    // checking the whole cross product (billions of candidates), the slots are decided in the
    // order the calls reach them: a reached slot takes each of its values in turn (adding what
    // they call), and once no undecided slot is reached the rest are null. Every candidate is
    // then checked by the policy, and the valid ones are kept as their ranks in the cross
    // product's order (the first factor fastest), so an index names the same composition as an
    // odometer over all factors would. The root of the search is the RaySetup and the
    // RayTraversal, the two most significant slots (the RaySetup is reached first; the
    // traversal is decided with it, and a candidate whose RaySetup does not reach a chosen
    // traversal is one the policy rejects): per pair the ranks are collected by light count,
    // sorted and compressed into a segment, so only one pair's ranks are ever held uncompressed.
    const std::size_t slotCount = functions.size();
    std::vector<std::vector<std::uint32_t>> calls(slotCount);  // per factor value: the slots it calls
    std::vector<int> nullValue(slotCount, -1);                   // the value that is no implementation
    for (std::size_t i = 0; i < slotCount; ++i)
        for (std::size_t v = 0; v < functions[i].size(); ++v) {
            std::uint32_t mask = 0;
            for (const ShaderFunction* f : functions[i][v])
                for (std::size_t j = 0; j < slotCount; ++j)
                    if (f->mayCall(slots()[j].name)) mask |= std::uint32_t(1) << j;
            calls[i].push_back(mask);
            const bool none = slots()[i].isTemplate ? functions[i][v].empty() : _factors[i].values[v] == "null";
            if (none) nullValue[i] = int(v);
        }
    if (slotCount > 32) throw std::logic_error("PermutationSpace: more slots than a mask holds");
    std::uint64_t product = 1;  // of the factors' sizes: the ranks' range
    for (const Factor& f : _factors) {
        if (f.values.empty() || product > std::numeric_limits<std::uint64_t>::max() / f.values.size())
            throw std::logic_error("PermutationSpace: the cross product outgrows 64-bit ranks");
        product *= f.values.size();
    }
    std::vector<std::uint64_t> weight(_factors.size(), 1);  // rank = sum of value index * weight
    for (std::size_t i = 1; i < _factors.size(); ++i) weight[i] = weight[i - 1] * _factors[i - 1].values.size();
    std::vector<std::uint8_t> choice(_factors.size(), 0);
    SlotFunctions chosen(slotCount);
    std::vector<std::vector<std::uint64_t>> byLights(_factors.back().values.size());  // one RaySetup's ranks
    auto slotNamed = [](const char* name) {
        return std::size_t(std::find_if(slots().begin(), slots().end(), [&](const SlotInfo& s) { return s.name == name; }) -
                           slots().begin());
    };
    const std::size_t setup = slotNamed("RaySetup"), traversal = slotNamed("RayTraversal");
    if (setup + 1 != slotCount || traversal + 2 != slotCount)
        throw std::logic_error("PermutationSpace: RaySetup and RayTraversal must be the two most significant slots");
    std::function<void(std::uint32_t, std::uint32_t)> decide = [&](std::uint32_t decided, std::uint32_t reached) {
        const std::uint32_t open = reached & ~decided;
        if (open) {
            const std::size_t i = std::size_t(__builtin_ctz(open));
            for (std::size_t v = 0; v < functions[i].size(); ++v) {
                choice[i] = std::uint8_t(v);
                decide(decided | std::uint32_t(1) << i, reached | calls[i][v]);
            }
            return;
        }
        for (std::size_t i = 0; i < slotCount; ++i)
            if (!(decided & std::uint32_t(1) << i)) {
                if (nullValue[i] < 0) return;  // a slot nothing calls must be null
                choice[i] = std::uint8_t(nullValue[i]);
            }
        for (std::size_t i = 0; i < slotCount; ++i) chosen[i] = functions[i][choice[i]];
        std::uint64_t rank = 0;
        for (std::size_t i = 0; i < slotCount; ++i) rank += choice[i] * weight[i];
        if (const std::optional<LightUse> use = _policy.validWithLights(chosen))
            for (std::size_t n = 0; n < _factors.back().values.size(); ++n)
                if (CompositionPolicy::lightCountFits(*use, unsigned(n))) byLights[n].push_back(rank + n * weight.back());
    };
    // Segments in index order: light count first (the most significant factor), then RaySetup,
    // then RayTraversal.
    std::vector<std::vector<Segment>> segments(byLights.size());
    const std::uint32_t root = std::uint32_t(1) << setup | std::uint32_t(1) << traversal;
    for (std::size_t v = 0; v < functions[setup].size(); ++v) {
        for (std::size_t t = 0; t < functions[traversal].size(); ++t) {
            // A traversal the RaySetup does not call is null, as for any slot nothing reaches.
            const bool reached = calls[setup][v] & std::uint32_t(1) << traversal;
            if (!reached && int(t) != nullValue[traversal]) continue;
            choice[setup] = std::uint8_t(v);
            choice[traversal] = std::uint8_t(t);
            decide(root, root | calls[setup][v] | (reached ? calls[traversal][t] : 0));
            for (std::size_t n = 0; n < byLights.size(); ++n) {
                std::vector<std::uint64_t>& ranks = byLights[n];
                std::sort(ranks.begin(), ranks.end());
                Segment& segment = segments[n].emplace_back();
                segment.offsets.reserve(ranks.size());
                for (std::size_t k = 0; k < ranks.size(); ++k) {
                    // A new block every 4096 compositions, or where the offset would not fit 32 bits.
                    if (segment.blocks.empty() || k - segment.blocks.back().first >= 4096 ||
                        ranks[k] - segment.blocks.back().base > std::numeric_limits<std::uint32_t>::max())
                        segment.blocks.push_back({k, ranks[k]});
                    segment.offsets.push_back(std::uint32_t(ranks[k] - segment.blocks.back().base));
                }
                std::vector<std::uint64_t>().swap(ranks);
            }
        }
    }
    for (std::vector<Segment>& lights : segments)
        for (Segment& segment : lights) {
            if (segment.offsets.empty()) continue;
            segment.first = _size;
            _size += segment.offsets.size();
            _segments.push_back(std::move(segment));
        }
}

std::uint64_t PermutationSpace::rank(std::size_t index) const
{
    if (index >= _size) throw std::out_of_range("PermutationSpace: index " + std::to_string(index) + " of " + std::to_string(_size));
    auto s = std::upper_bound(_segments.begin(), _segments.end(), index,
                              [](std::size_t i, const Segment& segment) { return i < segment.first; });
    const Segment& segment = *std::prev(s);
    const std::size_t local = index - segment.first;
    auto b = std::upper_bound(segment.blocks.begin(), segment.blocks.end(), local,
                              [](std::size_t i, const Block& block) { return i < block.first; });
    return std::prev(b)->base + segment.offsets[local];
}

std::vector<std::uint8_t> PermutationSpace::choiceOf(std::uint64_t rank) const
{
    std::vector<std::uint8_t> choice(_factors.size());
    for (std::size_t i = 0; i < _factors.size(); ++i) {
        choice[i] = std::uint8_t(rank % _factors[i].values.size());
        rank /= _factors[i].values.size();
    }
    return choice;
}

Composition PermutationSpace::compose(const std::vector<std::uint8_t>& choice) const
{
    Composition c;
    for (std::size_t i = 0; i < _factors.size(); ++i) {
        const Factor& f = _factors[i];
        const std::string& value = f.values[choice[i]];
        if (f.name == "lights") c.lightCount = unsigned(std::stoul(value));
        else if (findSlot(f.name)->isTemplate) c.instances[f.name] = parseList(value);
        else c.choice[f.name] = value;
    }
    return c;
}

Composition PermutationSpace::at(std::size_t index) const
{
    return compose(choiceOf(rank(index)));
}

std::vector<std::size_t> PermutationSpace::pairwiseCover(const ValueFilter& allowed) const
{
    // Greedy: repeatedly take the candidate that covers the most uncovered pairs (the first such).
    // The candidates are, for each pair, the first composition holding it (so every pair can be
    // covered) and an even sample of the space (so the greedy has good choices): scanning every
    // valid composition for every choice took minutes once the space held tens of millions.
    const std::size_t n = _factors.size();
    std::vector<std::size_t> offset(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + _factors[i].values.size();
    const std::size_t values = offset[n];
    auto pairIndex = [&](std::size_t i, std::uint8_t a, std::size_t j, std::uint8_t b) {
        return (offset[i] + a) * values + offset[j] + b;
    };
    constexpr std::size_t none = ~std::size_t(0);
    std::vector<char> allowedValue(values, 1);  // per factor value
    if (allowed)
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t a = 0; a < _factors[i].values.size(); ++a) {
                const std::string& value = _factors[i].values[a];  // "[a,b]" for a template slot's instances
                allowedValue[offset[i] + a] =
                    allowed(_factors[i].name, value.front() == '[' ? parseList(value) : std::vector<std::string>{value});
            }
    auto inSubspace = [&](const std::vector<std::uint8_t>& v) {
        for (std::size_t i = 0; i < n; ++i)
            if (!allowedValue[offset[i] + v[i]]) return false;
        return true;
    };
    std::vector<std::size_t> witness(values * values, none);
    for (const Segment& segment : _segments)  // every composition in index order, decoded in turn
        for (std::size_t b = 0; b < segment.blocks.size(); ++b) {
            const std::size_t end = b + 1 < segment.blocks.size() ? segment.blocks[b + 1].first : segment.offsets.size();
            for (std::size_t local = segment.blocks[b].first; local < end; ++local) {
                const std::vector<std::uint8_t> v = choiceOf(segment.blocks[b].base + segment.offsets[local]);
                if (!inSubspace(v)) continue;
                const std::size_t k = segment.first + local;
                for (std::size_t i = 0; i < n; ++i)
                    for (std::size_t j = i + 1; j < n; ++j) {
                        std::size_t& w = witness[pairIndex(i, v[i], j, v[j])];
                        if (w == none) w = k;
                    }
            }
        }
    std::vector<std::size_t> candidates;
    std::size_t remaining = 0;
    for (std::size_t w : witness)
        if (w != none) candidates.push_back(w), ++remaining;
    const std::size_t stride = std::max<std::size_t>(1, _size / 100000);
    for (std::size_t k = 0; k < _size; k += stride)
        if (!allowed || inSubspace(choiceOf(rank(k)))) candidates.push_back(k);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    std::vector<std::vector<std::uint8_t>> decoded;  // the candidates' choices
    decoded.reserve(candidates.size());
    for (std::size_t k : candidates) decoded.push_back(choiceOf(rank(k)));

    std::vector<char> covered(values * values, 0);
    std::vector<std::size_t> chosen;
    while (remaining > 0) {
        std::size_t best = 0, bestGain = 0;
        for (std::size_t c = 0; c < candidates.size(); ++c) {
            const auto& v = decoded[c];
            std::size_t gain = 0;
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = i + 1; j < n; ++j) gain += !covered[pairIndex(i, v[i], j, v[j])];
            if (gain > bestGain) bestGain = gain, best = c;
        }
        if (bestGain == 0) break;
        const auto& v = decoded[best];
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                char& c = covered[pairIndex(i, v[i], j, v[j])];
                if (!c) c = 1, --remaining;
            }
        chosen.push_back(candidates[best]);
    }
    return chosen;
}

}  // namespace volren
