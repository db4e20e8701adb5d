#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/Slots.h>

#include <volume_model/ClipNode.h>
#include <volume_model/RenderSettings.h>
#include <volume_model/SpatialWeighting.h>

#include <osg/Notify>

#include <algorithm>
#include <cctype>
#include <mutex>
#include <set>

namespace volren {

namespace {

const std::string none = "null";

/// The node's and the pass's wishes for each slot.
struct Wishes
{
    const RenderSettings& settings;
    const PassSettings& pass;

    bool forcedNull(const std::string& slot) const { return settings.forceNull.count(slot) || pass.forceNull.count(slot); }
    /// The user's choice for `slot` ("null" when forced), or "" when the user named none.
    std::string named(const std::string& slot) const
    {
        if (forcedNull(slot)) return none;
        auto it = settings.functions.find(slot);
        return it == settings.functions.end() ? std::string() : it->second;
    }
    std::string chosen(const std::string& slot, const std::string& fallback) const
    {
        const std::string n = named(slot);
        return n.empty() ? fallback : n;
    }
    bool off(const std::string& slot) const { return named(slot) == none; }
};

std::string lower(std::string s)
{
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

LightUse CompositionPolicy::lightUseOf(const ShaderFunction& shading)
{
    // Implementations of unknown traits (shader-folder additions) may or may not loop over lights.
    return shading.traits.calls ? shading.traits.lights : LightUse::Optional;
}

std::string CompositionPolicy::defaultImplementation(const std::string& slot)
{
    static const std::map<std::string, std::string> defaults = {{"RaySetup", "box_intersection"},
                                                                {"RayTraversal", "dvr_front_to_back"},
                                                                {"Reconstruction", "trilinear"},
                                                                {"VolumeStorage", "texture"},
                                                                {"Classification", "tf1d"},
                                                                {"GradientInput", "scalar"},
                                                                {"Jitter", "hash"}};
    auto it = defaults.find(slot);
    return it == defaults.end() ? none : it->second;
}

std::string CompositionPolicy::neededImplementation(const std::string& slot)
{
    static const std::map<std::string, std::string> needed = {
        {"Illumination", "blinn_phong"}, {"Shading", "lighting"}, {"Gradient", "central"}, {"Weighting", "axes"}};
    auto it = needed.find(slot);
    return it == needed.end() ? defaultImplementation(slot) : it->second;
}

Composition CompositionPolicy::bare(const std::string& setup) const
{
    Composition c;
    for (const SlotInfo& slot : slots())
        if (!slot.isTemplate) c.choice[slot.name] = none;
    c.choice["RaySetup"] = setup;
    return c;
}

std::string CompositionPolicy::implementationForKind(const std::string& slot, const std::string& kind) const
{
    for (const std::string& name : _registry.names(slot))
        if (const ShaderFunction* f = _registry.find(slot, name); f && f->traits.clipKind == kind) return name;
    return {};
}

ChosenComposition CompositionPolicy::choose(const RenderSettings& settings, const SceneOffer& offer,
                                            const PassSettings& pass) const
{
    const Wishes wish{settings, pass};
    ChosenComposition out;
    const std::string setup = wish.chosen("RaySetup", defaultImplementation("RaySetup"));
    std::string traversal = wish.chosen("RayTraversal", defaultImplementation("RayTraversal"));
    if (const ShaderFunction* f = _registry.find("RayTraversal", traversal);
        f && f->traits.multiVolume && !f->traits.memberTraversal.empty()) {  // how it blends with others
        out.setTraversal = traversal;
        traversal = f->traits.memberTraversal;
    }
    if (setup == none || traversal == none) {  // nothing is marched, so nothing else can run
        out.composition = bare(setup);
        return out;
    }
    out.composition.choice["RayTraversal"] = traversal;
    chooseLighting(out, settings, offer, pass);
    for (const SlotInfo& slot : slots())
        if (!slot.isTemplate && !out.composition.choice.count(slot.name))
            out.composition.choice[slot.name] = wish.chosen(slot.name, defaultImplementation(slot.name));
    chooseClips(out, settings, offer, pass);
    chooseWeighting(out, settings, pass);
    if (out.composition.functionFor("Reconstruction") == none && wish.named("VolumeStorage").empty())
        out.composition.choice["VolumeStorage"] = none;  // nothing reads voxels
    else if (offer.exceedsTextureBudget && wish.named("VolumeStorage").empty())
        for (const std::string& name : _registry.names("VolumeStorage"))
            if (const ShaderFunction* f = _registry.find("VolumeStorage", name); f && f->traits.withinBudget) {
                out.composition.choice["VolumeStorage"] = name;
                break;
            }
    // Skipping, by default wherever an implementation takes the leaps the traversal can take
    // (the user's choice is checked, not replaced).
    if (wish.named("Acceleration").empty() && !offer.coarsePreview)
        for (const std::string& name : _registry.names("Acceleration"))
            if (const ShaderFunction* f = _registry.find("Acceleration", name); f && skippingFits(out.composition, *f)) {
                out.composition.choice["Acceleration"] = name;
                break;
            }
    // What the chosen implementations compile in for this scene (their hooks, in slot order).
    Composition& c = out.composition;
    for (const SlotInfo& slot : slots())
        if (const ShaderFunction* f = _registry.find(slot.name, c.functionFor(slot.name)); f && f->compileOptions) {
            const CompileOptions options = f->compileOptions({settings, offer, c});
            for (const auto& [name, value] : options.defines) c.defines[name] = value;
            c.keyFragments += options.keyFragment;
        }
    // The pass's debug output of sample counts: a macro of the whole program, no implementation's.
    if (pass.countSamples) {
        c.defines["VOLREN_COUNT_SAMPLES"] = "1";
        c.keyFragments += "countSamples=on;";
    }
    return out;
}

std::string CompositionPolicy::skippingMismatch(const ShaderFunction& acceleration, const ShaderFunction& traversal,
                                                const ShaderFunction& classification,
                                                const ShaderFunction& reconstruction)
{
    if (acceleration.traits.skips.empty()) return {};
    const std::string self = acceleration.slot + "/" + acceleration.name;
    if (traversal.traits.calls && traversal.traits.skips != acceleration.traits.skips)
        return self + " leaps by " + acceleration.traits.skips + ", RayTraversal/" + traversal.name +
               (traversal.traits.skips.empty() ? " takes no leaps" : " by " + traversal.traits.skips);
    if (acceleration.traits.skips == "opacity" && !classification.mayShow)
        return self + " needs a Classification with a CPU opacity mirror, not " + classification.name;
    if (reconstruction.traits.footprint < 0)
        return self + " needs a Reconstruction bounded by its voxels, not " + reconstruction.name;
    return {};
}

bool CompositionPolicy::skippingFits(const Composition& c, const ShaderFunction& acceleration) const
{
    // A default only where the traversal is known to take these leaps.
    const ShaderFunction* marcher = _registry.find("RayTraversal", c.functionFor("RayTraversal"));
    const ShaderFunction* classification = _registry.find("Classification", c.functionFor("Classification"));
    const ShaderFunction* reconstruction = _registry.find("Reconstruction", c.functionFor("Reconstruction"));
    if (!marcher || !classification || !reconstruction || !marcher->traits.calls || !marcher->mayCall("Acceleration") ||
        !marcher->traits.skipsByDefault || acceleration.traits.skips.empty() || acceleration.traits.approximates)
        return false;
    return skippingMismatch(acceleration, *marcher, *classification, *reconstruction).empty();
}

void CompositionPolicy::chooseLighting(ChosenComposition& out, const RenderSettings& settings, const SceneOffer& offer,
                                       const PassSettings& pass) const
{
    const Wishes wish{settings, pass};
    Composition& c = out.composition;
    const ShaderFunction* marcher = _registry.find("RayTraversal", c.choice["RayTraversal"]);
    const bool shades = !marcher || marcher->mayCall("Shading");
    const unsigned int lights =
        pass.lighting && shades ? unsigned(std::min<std::size_t>(offer.lights.size(), maxLights)) : 0;
    // Lights call for a lit Shading and its Illumination, unless the user turned one off; a
    // Shading that never calls an Illumination (debug views, null) gets none.
    std::string illumination =
        shades ? wish.chosen("Illumination", lights > 0 ? neededImplementation("Illumination") : none) : none;
    const std::string shading =
        shades ? wish.chosen("Shading", lights > 0 && illumination != none ? neededImplementation("Shading") : none)
               : none;
    const ShaderFunction* shader = _registry.find("Shading", shading);
    if (shader && !shader->mayCall("Illumination") && wish.named("Illumination").empty()) illumination = none;
    const bool needGradient = ((shading != none && (!shader || shader->mayCall("Gradient"))) ||
                               (marcher && marcher->requiresSlot("Gradient"))) &&
                              !wish.off("GradientInput");
    const std::string gradient = wish.chosen("Gradient", needGradient ? neededImplementation("Gradient") : none);
    c.choice["Illumination"] = illumination;
    c.choice["Shading"] = shading;
    c.choice["Gradient"] = gradient;
    c.choice["GradientInput"] = wish.chosen("GradientInput", gradient != none ? neededImplementation("GradientInput") : none);
    const LightUse use = shader ? lightUseOf(*shader) : LightUse::Optional;
    c.lightCount = use == LightUse::Optional || (use == LightUse::Required && illumination != none) ? lights : 0;
    if (shading == none) c.lightCount = 0;
}

void CompositionPolicy::chooseWeighting(ChosenComposition& out, const RenderSettings& settings,
                                        const PassSettings& pass) const
{
    // The node's spatial weighting wherever a chosen implementation weighs its samples by it.
    const Wishes wish{settings, pass};
    Composition& c = out.composition;
    const SpatialWeighting weighting = spatialWeighting(settings);
    if (wish.named("Weighting").empty() && !weighting.identity()) {
        bool weighs = false;
        for (const char* slot : {"RayTraversal", "Shadowing"})
            if (const ShaderFunction* f = _registry.find(slot, c.functionFor(slot));
                f && f->traits.calls && f->mayCall("Weighting"))
                weighs = true;
        if (weighs) {
            c.choice["Weighting"] = neededImplementation("Weighting");
        } else {
            static std::mutex told;  // once per traversal: the policy runs every cull
            static std::set<std::string> traversals;
            const std::lock_guard<std::mutex> lock(told);
            if (traversals.insert(c.functionFor("RayTraversal")).second)
                OSG_NOTICE << "volren: RayTraversal " << c.functionFor("RayTraversal")
                           << " does not weigh its samples: the spatial weighting (weightX/Y/Z) is not applied"
                           << std::endl;
        }
    }
}

void CompositionPolicy::chooseClips(ChosenComposition& out, const RenderSettings& settings, const SceneOffer& offer,
                                    const PassSettings& pass) const
{
    const Wishes wish{settings, pass};
    const ShaderFunction* shadowing = _registry.find("Shadowing", out.composition.functionFor("Shadowing"));
    const bool perSample = shadowing && shadowing->traits.clipsPerSample && !wish.off("ClipPosition");
    // Each clip goes to the slot whose named implementation handles its kind, else to the first
    // of ClipRay (whole rays: exact and cheap) and ClipPosition (per sample) that is on and has
    // an implementation for it; otherwise it is dropped.
    auto place = [&](const std::string& kind, const ClipInfo& clip) {
        for (const char* slot : {"ClipPosition", "ClipRay"})
            if (const ShaderFunction* f = _registry.find(slot, wish.named(slot)); f && f->traits.clipKind == kind) {
                out.composition.instances[slot].push_back(f->name);
                out.clips[slot].push_back(clip);
                return true;
            }
        for (const char* slot : {"ClipRay", "ClipPosition"}) {
            const std::string name = implementationForKind(slot, kind);
            if (wish.off(slot) || name.empty() || (perSample && kind != "depth" && std::string(slot) == "ClipRay")) continue;
            out.composition.instances[slot].push_back(name);
            out.clips[slot].push_back(clip);
            return true;
        }
        return false;
    };
    out.composition.instances["ClipRay"];
    out.composition.instances["ClipPosition"];
    // Kinds whole rays can be cut by come first, then the opaque geometry's depth, then the rest;
    // a Shadowing that samples off the view ray needs every shape per sample.
    std::vector<const ClipInfo*> rest;
    for (const ClipInfo& clip : offer.clips) {
        const std::string kind = clip.node->clipKind();
        if (implementationForKind("ClipRay", kind).empty() || perSample) rest.push_back(&clip);
        else place(kind, clip);
    }
    if (offer.opaqueGeometry) place("depth", ClipInfo{});
    for (const ClipInfo* clip : rest) place(clip->node->clipKind(), *clip);
}

std::map<std::string, std::vector<ClipInfo>> CompositionPolicy::assignClips(const Composition& composition,
                                                                           const SceneOffer& offer) const
{
    std::map<std::string, std::vector<ClipInfo>> out;
    for (const auto& [slot, names] : composition.instances) {
        std::set<std::size_t> used;
        for (const std::string& name : names) {
            const ShaderFunction* f = _registry.find(slot, name);
            ClipInfo clip;
            for (std::size_t i = 0; f && i < offer.clips.size(); ++i)
                if (!used.count(i) && f->traits.clipKind == offer.clips[i].node->clipKind()) {
                    clip = offer.clips[i];
                    used.insert(i);
                    break;
                }
            out[slot].push_back(clip);
        }
    }
    return out;
}

std::vector<std::string> CompositionPolicy::choosable(const std::string& slot) const
{
    std::vector<std::string> names = _registry.names(slot);
    for (const std::string& name : _registry.allNames(slot))
        if (const ShaderFunction* f = _registry.find(slot, name); f->traits.multiVolume && !f->traits.memberTraversal.empty())
            names.push_back(name);
    const std::string first = defaultImplementation(slot);
    if (auto it = std::find(names.begin(), names.end(), first); it != names.end()) std::rotate(names.begin(), it, it + 1);
    return names;
}

std::string CompositionPolicy::resolve(const std::string& slot, const std::string& value) const
{
    const std::string v = lower(value);
    if (v == "off" || v == "none" || v == "0" || v == "false") return none;
    if (v == "on" || v == "1" || v == "true") {  // a slot whose needed implementation is null has no "on"
        const std::string needed = neededImplementation(slot);
        return needed == none ? std::string() : needed;
    }
    for (const std::string& name : choosable(slot)) {
        if (name == v) return name;
        const ShaderFunction* f = _registry.find(slot, name);
        if (std::find(f->traits.aliases.begin(), f->traits.aliases.end(), v) != f->traits.aliases.end()) return name;
    }
    return {};
}

}  // namespace volren
