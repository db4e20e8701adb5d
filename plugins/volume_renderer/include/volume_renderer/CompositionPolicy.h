#pragma once
#include <volume_renderer/Composition.h>
#include <volume_renderer/PassSettings.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <osg/BoundingBox>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace volren {

struct RenderSettings;

/// What the scene offers one volume: its lights, the clip shapes that change it (in scene
/// order, in the volume's own coordinates) and whether opaque geometry is drawn before it.
struct SceneOffer
{
    std::vector<LightInfo> lights;  ///< lights in the VolumeNode's local coordinates
    std::vector<ClipInfo> clips;    ///< clip shapes that cut the volume
    bool opaqueGeometry = false;    ///< opaque polygons are drawn before the volumes
    /// The sampled level of the volume exceeds the node's memory budget or the largest 3D texture.
    bool exceedsTextureBudget = false;
    /// The volume's voxels in RAM are a coarse level of a file opened lazily: their value ranges
    /// do not bound the full resolution, so skipping is not chosen by default.
    bool coarsePreview = false;
};

/// A volume's composition with the clip each template instance binds: per template slot, one
/// ClipInfo per instance (an empty one where an instance has no shape, e.g. the depth clip).
struct ChosenComposition
{
    Composition composition;
    std::map<std::string, std::vector<ClipInfo>> clips;
    /// The multi-volume set traversal the volume's settings name (`traversal=additive`): used
    /// when it shares a ray with others (its own composition has that traversal's
    /// memberTraversal); empty: the policy's default for its kind.
    std::string setTraversal = {};
};

/// Volumes that the pass draws with one program (`shared`: a multi-volume set marching one
/// ray) or box by box; indices into the list given to CompositionPolicy::rayGroups.
struct RayGroup
{
    std::vector<std::size_t> members;
    bool shared = false;
};

/// Implementations a composition chooses, by slot (index in slots()): one for an ordinary slot,
/// one per instance for a template slot.
using SlotFunctions = std::vector<std::vector<const ShaderFunction*>>;

/// The one place that turns what the scene analysis found (lights, clip shapes, opaque
/// geometry, overlapping volumes, node and pass settings) into compositions. It owns the
/// defaults, the validity rules and which volumes may share one ray; it knows implementations
/// only through their ImplementationTraits. The pass, the permutation sweep, `volren bench`,
/// the reference setup and `--help-settings` all ask it.
class CompositionPolicy
{
public:
    explicit CompositionPolicy(const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance());

    /// Largest number of lights passed to one volume (more are ignored, with a warning).
    static constexpr unsigned int maxLights = 8;
    /// Implementation of `slot` when nothing in the settings or the scene asks for another.
    static std::string defaultImplementation(const std::string& slot);
    /// Implementation of `slot` when the scene needs that slot (lights need an Illumination and
    /// a lit Shading, a Shading needs a Gradient, ...); what a setting's "on" means.
    static std::string neededImplementation(const std::string& slot);

    /// How a Shading implementation uses lights (Optional when its traits are unknown).
    static LightUse lightUseOf(const ShaderFunction& shading);
    /// Why `acceleration` cannot leap in a composition of these implementations ("" when it can):
    /// the traversal must take its kind of leaps (a traversal of unknown traits may take any),
    /// the Reconstruction must stay within the voxels it reads, and leaps by opacity need the
    /// Classification's CPU mirror. The one skipping rule of choose() and the validity check.
    static std::string skippingMismatch(const ShaderFunction& acceleration, const ShaderFunction& traversal,
                                        const ShaderFunction& classification, const ShaderFunction& reconstruction);

    /// The composition for a volume with node `settings` given the `offer` and the `pass`.
    ChosenComposition choose(const RenderSettings& settings, const SceneOffer& offer, const PassSettings& pass) const;
    /// The clips the template instances of a given (forced) composition bind: each instance takes
    /// the next offered shape of its implementation's kind, or none.
    std::map<std::string, std::vector<ClipInfo>> assignClips(const Composition& composition, const SceneOffer& offer) const;

    /// Why `composition` breaks a validity rule (code that could never run or contradicts
    /// itself), or "" when it is valid. The rules, in terms of ImplementationTraits:
    /// - RaySetup null or RayTraversal null: nothing marches, so every other slot is null;
    /// - every implementation exists; multi-volume ones only in sets; `single` ones once;
    /// - a slot that no chosen implementation calls (transitively from the RaySetup) is null,
    ///   and a slot a chosen implementation `required` is real;
    /// - lights only for a Shading that uses them, at least one for a lit (Required) one.
    std::string invalidReason(const Composition& composition) const;
    /// Whether `composition` obeys the validity rules.
    bool isValid(const Composition& composition) const { return invalidReason(composition).empty(); }
    /// The same rules on resolved implementations (fast: sweeps check millions of candidates).
    bool isValid(const SlotFunctions& chosen, unsigned int lightCount) const;
    /// Whether `chosen` obeys every rule but the light count's, and then how many lights it may
    /// take (lightCountFits); nullopt when no light count makes it valid. One check for all counts.
    std::optional<LightUse> validWithLights(const SlotFunctions& chosen) const;
    /// Whether a composition whose Shading uses lights as `use` may take `lightCount` of them.
    static bool lightCountFits(LightUse use, unsigned int lightCount);

    /// Whether a volume drawn with `composition` may share a ray with overlapping volumes.
    bool canShareRay(const Composition& composition) const { return !memberKind(composition).empty(); }
    /// The kind of set member a volume drawn with `composition` is (its traversal's sharesRayAs),
    /// or "" when it cannot share a ray.
    std::string memberKind(const Composition& composition) const;
    /// Groups of volumes whose boxes' bounds (in one frame) overlap, transitively, each in the
    /// given order; a group is shared when it has several members, all may share a ray as the
    /// same kind of member and the compositions are not `forced`.
    std::vector<RayGroup> rayGroups(const std::vector<osg::BoundingBoxd>& bounds,
                                    const std::vector<const Composition*>& compositions, bool forced) const;
    /// The composition of a multi-volume set program over `members` (each member's own, all of
    /// one memberKind): the set owns the per-set slots (SlotInfo::perSet) and the opaque
    /// geometry's depth clip, so those leave the members (their compositions and clips are
    /// updated in place). Its traversal is the first member's setTraversal where it marches
    /// members of that kind, else the one that combines their media, else the first that marches
    /// them; members of a traversal that takes no leaps lose their Acceleration.
    ChosenComposition setComposition(std::vector<ChosenComposition>& members) const;

    /// Implementations of `slot` a user may name, default first: those a single volume's
    /// composition may choose, and the multi-volume traversals with a memberTraversal.
    std::vector<std::string> choosable(const std::string& slot) const;
    /// The implementation of `slot` a user's `value` names (its name or an alias; off, none,
    /// false, 0 = null; on, true, 1 = the needed one), or "" when none.
    std::string resolve(const std::string& slot, const std::string& value) const;
    /// The registry the implementations come from.
    const ShaderFunctionRegistry& registry() const { return _registry; }

    /// The multi-volume traversal setComposition() gives `members` (null: none marches their
    /// kind); for one volume, the set traversal it is marched by where it shares a ray.
    const ShaderFunction* setTraversal(const std::vector<ChosenComposition>& members) const;

private:
    Composition bare(const std::string& setup) const;
    std::string implementationForKind(const std::string& slot, const std::string& kind) const;
    void chooseLighting(ChosenComposition& out, const RenderSettings& settings, const SceneOffer& offer,
                        const PassSettings& pass) const;
    void chooseClips(ChosenComposition& out, const RenderSettings& settings, const SceneOffer& offer,
                     const PassSettings& pass) const;
    void chooseWeighting(ChosenComposition& out, const RenderSettings& settings, const PassSettings& pass) const;
    bool skippingFits(const Composition& c, const ShaderFunction& acceleration) const;

    struct Rules;
    std::optional<LightUse> check(const SlotFunctions& chosen, bool inSet,
                                  const std::function<void(const std::string&)>* fail) const;

    const ShaderFunctionRegistry& _registry;
    std::shared_ptr<const Rules> _rules;  ///< the traits as slot bit masks, per implementation
};

}  // namespace volren
