// CompositionPolicy's validity rules, in terms of the implementations' traits. The traits are
// turned into bit masks over slots() once per policy, so a sweep checks millions of candidate
// compositions in a few seconds.
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/Slots.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

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
    std::unordered_map<const ShaderFunction*, Function> functions;
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
    Function find(const ShaderFunction* f) const
    {
        auto it = functions.find(f);
        return it == functions.end() ? of(*f) : it->second;  // added to the registry later
    }
};

CompositionPolicy::CompositionPolicy(const ShaderFunctionRegistry& registry) : _registry(registry)
{
    if (slots().size() > 8 * sizeof(Mask)) throw std::logic_error("CompositionPolicy: more slots than a rule mask holds");
    auto rules = std::make_shared<Rules>();
    for (const SlotInfo& s : slots())
        for (const std::string& name : registry.allNames(s.name)) {
            const ShaderFunction* f = registry.find(s.name, name);
            rules->functions[f] = Rules::of(*f);
        }
    _rules = rules;
}

bool CompositionPolicy::check(const SlotFunctions& chosen, unsigned int lightCount, bool inSet,
                              const std::function<void(const std::string&)>* fail) const
{
    auto reject = [&](auto message) {
        if (fail) (*fail)(message());
        return false;
    };
    const Rules& rules = *_rules;
    const auto& all = slots();
    auto real = [&](std::size_t i) { return all[i].isTemplate ? !chosen[i].empty() : !rules.find(chosen[i].front()).null; };
    Mask realMask = 0;
    for (std::size_t i = 0; i < all.size(); ++i) realMask |= real(i) ? Mask(1) << i : 0;

    if (!real(rules.setup) || !real(rules.traversal)) {  // nothing marches: everything else null
        if ((realMask & ~(Mask(1) << rules.setup)) == 0 && lightCount == 0) return true;
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
        for (const ShaderFunction* f : chosen[i]) reached |= rules.find(f).calls & ((Mask(1) << all.size()) - 1);
    }
    for (std::size_t i = 0; i < all.size(); ++i) {
        const bool isReached = reached & (Mask(1) << i);
        if (!isReached && real(i)) return reject([&] { return "nothing calls " + all[i].name + ", so it must be null"; });
        if (!isReached) continue;
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
    const LightUse use = (reached & (Mask(1) << rules.shading)) ? lightUseOf(*shading) : LightUse::None;
    if (use == LightUse::None && lightCount > 0)
        return reject([&] { return "Shading/" + shading->name + " uses no lights"; });
    if (use == LightUse::Required && lightCount == 0)
        return reject([&] { return "Shading/" + shading->name + " needs a light"; });
    return true;
}

bool CompositionPolicy::isValid(const SlotFunctions& chosen, unsigned int lightCount) const
{
    return check(chosen, lightCount, false, nullptr);
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
    check(chosen, c.lightCount, !c.members.empty(), &fail);
    return reason;
}

}  // namespace volren
