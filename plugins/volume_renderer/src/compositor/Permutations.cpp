#include <volume_renderer/Permutations.h>
#include <volume_renderer/Slots.h>

#include <algorithm>
#include <set>
#include <sstream>

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

    // Odometer over all factors; keep the valid ones.
    std::vector<std::uint8_t> choice(_factors.size(), 0);
    SlotFunctions chosen(functions.size());
    while (true) {
        for (std::size_t i = 0; i < functions.size(); ++i) chosen[i] = functions[i][choice[i]];
        if (_policy.isValid(chosen, unsigned(choice.back()))) _valid.push_back(choice);
        std::size_t i = 0;
        while (i < choice.size() && ++choice[i] == _factors[i].values.size()) choice[i++] = 0;
        if (i == choice.size()) break;
    }
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
    return compose(_valid.at(index));
}

std::vector<std::size_t> PermutationSpace::pairwiseCover() const
{
    // Greedy: repeatedly take the valid composition that covers the most uncovered pairs.
    const std::size_t n = _factors.size();
    std::vector<std::size_t> offset(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + _factors[i].values.size();
    const std::size_t values = offset[n];
    auto pairIndex = [&](std::size_t i, std::uint8_t a, std::size_t j, std::uint8_t b) {
        return (offset[i] + a) * values + offset[j] + b;
    };
    std::vector<char> needed(values * values, 0), covered(values * values, 0);
    for (const auto& v : _valid)
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) needed[pairIndex(i, v[i], j, v[j])] = 1;
    std::size_t remaining = 0;
    for (char c : needed) remaining += c;

    std::vector<std::size_t> chosen;
    while (remaining > 0) {
        std::size_t best = 0, bestGain = 0;
        for (std::size_t k = 0; k < _valid.size(); ++k) {
            const auto& v = _valid[k];
            std::size_t gain = 0;
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = i + 1; j < n; ++j) gain += !covered[pairIndex(i, v[i], j, v[j])];
            if (gain > bestGain) bestGain = gain, best = k;
        }
        if (bestGain == 0) break;
        const auto& v = _valid[best];
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                char& c = covered[pairIndex(i, v[i], j, v[j])];
                if (!c) c = 1, --remaining;
            }
        chosen.push_back(best);
    }
    return chosen;
}

}  // namespace volren
