// CompositionPolicy's validity rules, in terms of the implementations' traits. The traits are
// turned into bit masks over slots() once per policy, so a sweep checks millions of candidate
// compositions in a few seconds.
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/Slots.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace volren {

namespace {

using Mask = std::uint32_t;

std::size_t slotIndex(const std::string& name)
{
    const auto& all = slots();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (all[i].name == name) return i;
    return all.size();
}

Mask maskOf(const SlotList& names)
{
    Mask m = 0;
    for (const std::string& n : names)
        if (std::size_t i = slotIndex(n); i < slots().size()) m |= Mask(1) << i;
    return m;
}

}  // namespace

/// One implementation's traits as masks over slots().
struct CompositionPolicy::Rules
{
    struct Function
    {
        Mask calls = ~Mask(0);  ///< unknown calls: any slot
        Mask required = 0;
        bool null = false;
    };
    /// Open addressing by the implementation's address (a power-of-two table at most a quarter
    /// full, linear probing): the sweep looks up rules about two billion times, and a node-based
    /// map's bucket walk was most of its enumeration time.
    std::vector<std::pair<const ShaderFunction*, Function>> table;
    std::size_t setup = slotIndex("RaySetup"), traversal = slotIndex("RayTraversal"), shading = slotIndex("Shading");
    std::size_t classification = slotIndex("Classification"), reconstruction = slotIndex("Reconstruction");
    std::size_t acceleration = slotIndex("Acceleration");

    static Function of(const ShaderFunction& f)
    {
        Function out;
        if (f.traits.calls) out.calls = maskOf(*f.traits.calls);
        out.required = maskOf(f.traits.required);
        out.null = f.name == "null";
        return out;
    }
    std::size_t slotOf(const ShaderFunction* f) const
    {
        return (reinterpret_cast<std::uintptr_t>(f) >> 4) & (table.size() - 1);
    }
    void add(const ShaderFunction* f)
    {
        std::size_t i = slotOf(f);
        while (table[i].first && table[i].first != f) i = (i + 1) & (table.size() - 1);
        table[i] = {f, of(*f)};
    }
    Function find(const ShaderFunction* f) const
    {
        for (std::size_t i = slotOf(f);; i = (i + 1) & (table.size() - 1)) {
            if (table[i].first == f) return table[i].second;
            if (!table[i].first) return of(*f);  // added to the registry later
        }
    }
};

CompositionPolicy::CompositionPolicy(const ShaderFunctionRegistry& registry) : _registry(registry)
{
    if (slots().size() > 8 * sizeof(Mask)) throw std::logic_error("CompositionPolicy: more slots than a rule mask holds");
    auto rules = std::make_shared<Rules>();
    std::vector<const ShaderFunction*> all;
    for (const SlotInfo& s : slots())
        for (const std::string& name : registry.allNames(s.name)) all.push_back(registry.find(s.name, name));
    std::size_t size = 16;
    while (size < 4 * all.size()) size *= 2;
    rules->table.assign(size, {nullptr, {}});
    for (const ShaderFunction* f : all) rules->add(f);
    _rules = rules;
}

std::optional<LightUse> CompositionPolicy::check(const SlotFunctions& chosen, bool inSet,
                                                const std::function<void(const std::string&)>* fail) const
{
    auto reject = [&](auto message) -> std::optional<LightUse> {
        if (fail) (*fail)(message());
        return std::nullopt;
    };
    const Rules& rules = *_rules;
    const auto& all = slots();
    // Each chosen implementation's rule looked up once, gathered per slot: the sweep's space
    // checks about a hundred million candidates, and the lookups were most of its time.
    Mask realMask = 0;
    std::array<Mask, 8 * sizeof(Mask)> callsOf{}, requiredOf{};
    for (std::size_t i = 0; i < all.size(); ++i)
        for (const ShaderFunction* f : chosen[i]) {
            const Rules::Function rule = rules.find(f);
            callsOf[i] |= rule.calls;
            requiredOf[i] |= rule.required;
            if (all[i].isTemplate || !rule.null) realMask |= Mask(1) << i;
        }
    auto real = [&](std::size_t i) { return (realMask >> i) & 1; };

    if (!real(rules.setup) || !real(rules.traversal)) {  // nothing marches: everything else null
        if ((realMask & ~(Mask(1) << rules.setup)) == 0) return LightUse::None;
        return reject([] { return std::string("nothing marches (RaySetup or RayTraversal null): every other slot must be null"); });
    }
    for (std::size_t i = 0; i < all.size(); ++i)
        for (const ShaderFunction* f : chosen[i]) {
            if (f->traits.multiVolume && !inSet)
                return reject([&] { return f->slot + "/" + f->name + " exists only in multi-volume sets"; });
            if (f->traits.single && std::count(chosen[i].begin(), chosen[i].end(), f) > 1)
                return reject([&] { return f->slot + "/" + f->name + " may appear once"; });
        }
    // Slots reached from the RaySetup through the chosen implementations' calls.
    Mask reached = Mask(1) << rules.setup, done = 0;
    while (Mask todo = reached & ~done) {
        const std::size_t i = std::size_t(__builtin_ctz(todo));
        done |= Mask(1) << i;
        reached |= callsOf[i] & ((Mask(1) << all.size()) - 1);
    }
    for (std::size_t i = 0; i < all.size(); ++i) {
        const bool isReached = reached & (Mask(1) << i);
        if (!isReached && real(i)) return reject([&] { return "nothing calls " + all[i].name + ", so it must be null"; });
        if (!isReached) continue;
        if (requiredOf[i] & ~realMask)
            for (const ShaderFunction* f : chosen[i])
                if (Mask missing = rules.find(f).required & ~realMask)
                    return reject([&] {
                        return f->slot + "/" + f->name + " needs a real " + all[std::size_t(__builtin_ctz(missing))].name;
                    });
    }
    if (const ShaderFunction* f = chosen[rules.acceleration].front(); !f->traits.skips.empty() && real(rules.acceleration))
        if (std::string why = skippingMismatch(*f, *chosen[rules.traversal].front(), *chosen[rules.classification].front(),
                                               *chosen[rules.reconstruction].front());
            !why.empty())
            return reject([&] { return why; });
    const ShaderFunction* shading = chosen[rules.shading].front();
    return (reached & (Mask(1) << rules.shading)) ? lightUseOf(*shading) : LightUse::None;
}

bool CompositionPolicy::lightCountFits(LightUse use, unsigned int lightCount)
{
    return use == LightUse::None ? lightCount == 0 : use == LightUse::Required ? lightCount > 0 : true;
}

bool CompositionPolicy::isValid(const SlotFunctions& chosen, unsigned int lightCount) const
{
    const std::optional<LightUse> use = check(chosen, false, nullptr);
    return use && lightCountFits(*use, lightCount);
}

std::optional<LightUse> CompositionPolicy::validWithLights(const SlotFunctions& chosen) const
{
    return check(chosen, false, nullptr);
}

std::string CompositionPolicy::invalidReason(const Composition& c) const
{
    SlotFunctions chosen;
    for (const SlotInfo& s : slots()) {
        std::vector<const ShaderFunction*>& mine = chosen.emplace_back();
        const std::vector<std::string> names = s.isTemplate ? c.instancesOf(s.name) : std::vector{c.functionFor(s.name)};
        for (const std::string& name : names) {
            const ShaderFunction* f = _registry.find(s.name, name);
            if (!f) return "no implementation " + s.name + "/" + name;
            mine.push_back(f);
        }
    }
    std::string reason;
    const std::function<void(const std::string&)> fail = [&](const std::string& why) { reason = why; };
    const std::optional<LightUse> use = check(chosen, !c.members.empty(), &fail);
    if (!use || lightCountFits(*use, c.lightCount)) return reason;
    if (_rules->find(chosen[_rules->setup].front()).null || _rules->find(chosen[_rules->traversal].front()).null)
        return "nothing marches (RaySetup or RayTraversal null): every other slot must be null";
    const std::string& shading = chosen[_rules->shading].front()->name;
    return "Shading/" + shading + (*use == LightUse::None ? " uses no lights" : " needs a light");
}

}  // namespace volren
