// CompositionPolicy: which volumes march one ray together, and the program of such a set.
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/Slots.h>

#include <algorithm>
#include <numeric>

namespace volren {

std::string CompositionPolicy::memberKind(const Composition& composition) const
{
    const ShaderFunction* traversal = _registry.find("RayTraversal", composition.functionFor("RayTraversal"));
    if (!traversal || composition.functionFor("RaySetup") == "null") return {};
    return traversal->traits.sharesRayAs;
}

std::vector<RayGroup> CompositionPolicy::rayGroups(const std::vector<osg::BoundingBoxd>& bounds,
                                                   const std::vector<const Composition*>& compositions,
                                                   bool forced) const
{
    std::vector<std::size_t> group(bounds.size());
    std::iota(group.begin(), group.end(), std::size_t(0));
    auto root = [&](std::size_t i) {
        while (group[i] != i) i = group[i] = group[group[i]];
        return i;
    };
    auto overlap = [](const osg::BoundingBoxd& a, const osg::BoundingBoxd& b) {
        for (int axis = 0; axis < 3; ++axis)
            if (!(a._min[axis] < b._max[axis] && b._min[axis] < a._max[axis])) return false;
        return true;
    };
    for (std::size_t i = 0; i < bounds.size(); ++i)
        for (std::size_t j = i + 1; j < bounds.size(); ++j)
            if (overlap(bounds[i], bounds[j])) group[root(j)] = root(i);
    std::vector<RayGroup> out;
    std::map<std::size_t, std::size_t> index;
    for (std::size_t i = 0; i < bounds.size(); ++i) {
        auto [it, added] = index.emplace(root(i), out.size());
        if (added) out.emplace_back();
        out[it->second].members.push_back(i);
    }
    for (RayGroup& g : out) {
        const std::string kind = memberKind(*compositions[g.members.front()]);
        g.shared = g.members.size() > 1 && !forced && !kind.empty() &&
                   std::all_of(g.members.begin(), g.members.end(),
                               [&](std::size_t i) { return memberKind(*compositions[i]) == kind; });
    }
    return out;
}

const ShaderFunction* CompositionPolicy::setTraversal(const std::vector<ChosenComposition>& members) const
{
    // The traversals that march members of this kind: a member's named one, else the one that
    // combines media, else the first in name order.
    const std::string kind = members.empty() ? std::string() : memberKind(members.front().composition);
    std::vector<const ShaderFunction*> fitting;
    for (const std::string& name : _registry.allNames("RayTraversal")) {
        const ShaderFunction* f = _registry.find("RayTraversal", name);
        if (f->traits.multiVolume && f->traits.sharesRayAs == kind) fitting.push_back(f);
    }
    for (const ShaderFunction* f : fitting)
        if (f->name == members.front().setTraversal) return f;
    for (const ShaderFunction* f : fitting)
        if (f->traits.combines == "media") return f;
    return fitting.empty() ? nullptr : fitting.front();
}

ChosenComposition CompositionPolicy::setComposition(std::vector<ChosenComposition>& members) const
{
    // The set's own slots: its box, the set traversal, the first member's jitter, the depth of
    // opaque geometry; everything a sample needs comes from the members' compositions.
    ChosenComposition set;
    set.composition = bare(defaultImplementation("RaySetup"));
    const ShaderFunction* traversal = setTraversal(members);
    if (traversal) set.composition.choice["RayTraversal"] = traversal->name;
    if (!members.empty()) set.composition.choice["Jitter"] = members.front().composition.functionFor("Jitter");
    bool depth = false;
    for (ChosenComposition& m : members) {
        for (const SlotInfo& s : slots())
            if (s.perSet && s.name != "RayTraversal")
                m.composition.choice[s.name] = s.name == "RaySetup" ? defaultImplementation("RaySetup") : "null";
        if (traversal && traversal->traits.skips.empty()) m.composition.choice["Acceleration"] = "null";
        std::vector<std::string>& rays = m.composition.instances["ClipRay"];
        std::vector<ClipInfo>& clips = m.clips["ClipRay"];
        clips.resize(rays.size());
        for (std::size_t k = rays.size(); k-- > 0;) {
            const ShaderFunction* f = _registry.find("ClipRay", rays[k]);
            if (!f || f->traits.clipKind != "depth") continue;
            depth = true;
            rays.erase(rays.begin() + std::ptrdiff_t(k));
            clips.erase(clips.begin() + std::ptrdiff_t(k));
        }
        set.composition.members.push_back(m.composition);
    }
    if (depth) {
        set.composition.instances["ClipRay"] = {implementationForKind("ClipRay", "depth")};
        set.clips["ClipRay"] = {ClipInfo{}};
    }
    return set;
}

}  // namespace volren
