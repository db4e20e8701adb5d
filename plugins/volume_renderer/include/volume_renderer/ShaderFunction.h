#pragma once
#include <volume_renderer/BindContext.h>

#include <volume_model/ParameterDecl.h>
#include <volume_model/ReferenceModel.h>

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace volren {

/// A uniform an implementation reads (the compositor declares it once in the program).
struct UniformDecl
{
    std::string name = {};       ///< GLSL name, `volren_` prefixed
    std::string glslType = {};   ///< "float", "vec2", "mat4", ...
    std::string arraySize = {};  ///< GLSL array size expression, empty for a single value
    bool shared = false;    ///< one value per program: not renamed per template instance
    /// Read by the ray caster only, never by the implementation's compute build (buildFile), so
    /// a change of it does not rebuild the auxiliary volume (the opaque geometry's shadow maps).
    bool rayCasterOnly = false;
    /// Set from the scene's lights: a change of it rebuilds only auxiliary volumes whose build
    /// reads the lights (AuxBuild::readsLights).
    bool perLight = false;
};

/// A texture an implementation samples; the compositor gives each distinct name a unit.
struct TextureDecl
{
    std::string name = {};         ///< GLSL sampler name
    std::string samplerType = {};  ///< "sampler3D", "sampler1D", ...
    bool shared = false;      ///< one texture per program: not renamed per template instance
    bool rayCasterOnly = false;  ///< see UniformDecl::rayCasterOnly
};

/// A list of slot names.
using SlotList = std::vector<std::string>;

/// Settings (`--set` keys and values) of one row of `volren bench`'s default matrix.
using BenchRow = std::vector<std::pair<std::string, std::string>>;

/// How a Shading implementation uses the scene's lights.
enum class LightUse
{
    None,      ///< never sees a light (the composition has no lights)
    Optional,  ///< loops over the lights when there are some (debug views)
    Required,  ///< lit: needs at least one light and a real Illumination
};

/// What the composition policy needs to know about an implementation, declared next to it in
/// its slot's functions/<Slot>.cpp. Nothing else in the renderer names implementations.
struct ImplementationTraits
{
    /// Slots its GLSL calls (with its includes); unset = unknown, any may be called. A slot that
    /// no chosen implementation calls is null in every composition (it would be dead code).
    std::optional<SlotList> calls = {};
    /// Slots among `calls` that must be real (not null) whenever this implementation is chosen.
    SlotList required = {};
    /// RayTraversal: what kind of member of a multi-volume set a volume drawn with it is, so that
    /// overlapping volumes drawn alike share one ray: "emission_absorption" (their media add or
    /// their images add) or "maximum" (each member's maximum, classified; the maxima add).
    /// Empty: it never shares a ray (each volume is drawn box by box). A multi-volume set's
    /// traversal: the kind of members it marches.
    std::string sharesRayAs = {};
    /// A multi-volume set's RayTraversal that users may name for a volume: the traversal the
    /// volume is drawn with alone and as a member. Empty: only the policy picks it.
    std::string memberTraversal = {};
    /// A multi-volume set's RayTraversal: how its members combine, as the reference renderer
    /// integrates them (ReferenceScene::Blending): "media" (optical depths add, emissions mix),
    /// "images" (each member's own emission-absorption image, added: no member occludes another),
    /// "maxima" (each member's classified maximum, added).
    std::string combines = {};
    /// RayTraversal: reports an opaque surface hit and writes its depth (isosurface).
    bool writesDepth = false;
    /// Shading: whether and how it uses the scene's lights.
    LightUse lights = LightUse::None;
    /// Template slots: the kind of clip one instance implements ("plane", "box", "ellipsoid",
    /// "mask": ClipNode::clipKind(); "depth": the opaque geometry's depth). Empty: none.
    std::string clipKind = {};
    /// Template slots: at most one instance per composition (one depth buffer per camera).
    bool single = false;
    /// Part of multi-volume set programs only (the set's traversal, the per-member glue): never
    /// chosen for a single volume, left out of ShaderFunctionRegistry::names().
    bool multiVolume = false;
    /// Reconstruction: how many voxels beyond a sample's cell of voxels it reads, with weights that
    /// keep the result within the values read (1 trilinear and nearest, 2 tricubic B-spline);
    /// -1: not bounded by the voxels, so nothing may be inferred from a region's value range.
    int footprint = -1;
    /// Acceleration: what its leaps rest on; RayTraversal: the leaps it can take. "opacity":
    /// samples the Classification's CPU mirror (ShaderFunction::mayShow) proves transparent
    /// from a region's value range (volren_skip); "extremum": samples that cannot pass the ray's
    /// running maximum or minimum (MIP, MinIP; the volren_skip overload with a level). Both need
    /// a Reconstruction with a footprint. Empty: none (an Acceleration with none leaps nowhere).
    std::string skips = {};
    /// RayTraversal: the policy gives it skipping unasked. False where the bench measured the
    /// leaps' queries costing more than they save on the shared CTs (MIP: the running maximum
    /// rarely rules a cell out before the brightest structure is met); `acceleration=range` asks.
    bool skipsByDefault = true;
    /// VolumeStorage: keeps the voxels within the node's memory budget, whatever the volume's
    /// size; the policy chooses it for volumes that exceed the budget or the largest 3D texture.
    bool withinBudget = false;
    /// Acceleration: it changes the image, within a bound it states (adaptive steps), so the
    /// policy never chooses it unless asked; skipping alone is exact.
    bool approximates = false;
    /// Shadowing: it samples the volume away from the view ray, so every clip shape must be
    /// known per sample (the policy puts clip planes in ClipPosition instead of ClipRay).
    bool clipsPerSample = false;
    /// Other names users may give it in settings ("dvr" for dvr_front_to_back).
    std::vector<std::string> aliases = {};
};

struct Composition;
struct RenderSettings;
struct SceneOffer;

/// What an implementation compiles in for one scene: values of its declared macros and a
/// fragment of the program key that tells them apart (programs are cached by key).
struct CompileOptions
{
    std::map<std::string, std::string> defines = {};  ///< macro name -> value
    std::string keyFragment = {};                      ///< "name=value;" where not the default
};

/// What a compile-options hook sees: the node's settings, the scene's offer and the composition
/// chosen so far (every slot chosen, the lights counted).
struct CompileContext
{
    const RenderSettings& settings;
    const SceneOffer& offer;
    const Composition& composition;
};

/// One implementation of a shader-function slot: a GLSL file plus what it needs.
/// The GLSL file states its slot and signature at the top and declares no uniforms itself:
/// the compositor emits the declarations listed here, once per program (per instance for
/// template slots, with the instance suffix). Built with named fields:
/// `{.slot = "Illumination", .name = "lambert", .traits = {.calls = SlotList{}}}`.
/// Loop iterations an implementation's own loops take per view sample, at most: for drivers
/// that end a pixel's loops after a fixed number of iterations (LoopBudget.h).
struct LoopCost
{
    double perSample = 0.0;  ///< per view sample it is called for
    double perLight = 0.0;   ///< per view sample and light
};

struct ShaderFunction
{
    std::string slot = {};                   ///< slot name, e.g. "RayTraversal"
    std::string name = {};                   ///< implementation name, e.g. "dvr_front_to_back"
    std::string file = {};                   ///< fragment source relative to a shader folder; empty: <slot>/<name>.glsl
    std::string vertexFile = {};             ///< vertex source (RaySetup only), relative path
    /// A compute shader (its main) that builds this implementation's auxiliary volume on the GPU
    /// through the composition's VolumeStorage, Reconstruction, Classification and ClipPosition;
    /// the compositor composes it with them (ComposedProgram::builds). Empty: none.
    std::string buildFile = {};
    std::vector<std::string> includes = {};  ///< helper files emitted (once) before `file`
    std::vector<UniformDecl> uniforms = {};  ///< uniforms it reads
    std::vector<TextureDecl> textures = {};  ///< samplers it reads
    std::vector<std::string> needs = {};     ///< auxiliary data the pass must make (AuxKind names)
    /// Its parameters (slot and implementation are filled in at registration): what `--set`,
    /// scene files, the panel and its bind read. Keys are unique across the registry.
    std::vector<ParameterDecl> parameters = {};
    /// Macros its GLSL reads, each with the value it has where no hook set one (compositions
    /// made without the policy, e.g. by permutation sweeps); emitted in the program's header.
    std::map<std::string, std::string> defines = {};
    /// Sets this scene's values of `defines` (e.g. how many curve segments to evaluate). Unset:
    /// the defaults hold.
    std::function<CompileOptions(const CompileContext&)> compileOptions = {};
    std::function<void(BindContext&)> bind = {};  ///< sets this frame's uniform values and textures
    ImplementationTraits traits = {};        ///< what the composition policy knows of it
    /// How the CPU reference models it (the reference selects its model by this). Unset: not
    /// declared (a plugin's, or a slot the reference does not model per implementation).
    std::optional<ReferenceModel> reference = {};
    /// Its rows in `volren bench`'s default matrix: each chooses it, with these settings on top
    /// (an empty row: it alone). None: the bench measures it only when asked.
    std::vector<BenchRow> benchRows = {};
    /// Its loops' iterations per view sample, at most, for the bound context (a lit Shading's
    /// light loop, a shadow march, cones). Unset: it loops over nothing of that size.
    std::function<LoopCost(const BindContext&)> loops = {};
    /// Classification: makes, for a binding, the CPU mirror of its opacity over texel values: a
    /// predicate false only when every texel value in [lo, hi] classifies to zero opacity (used
    /// for empty-space skipping while that binding lasts). Unset: unknown, nothing is skipped.
    std::function<std::function<bool(double lo, double hi)>(const BindContext&)> mayShow = {};
    /// Classification: makes, for a binding, the CPU mirror of how much its classification may
    /// change over texel values [lo, hi]: a bound on the difference of the opacity, and of each
    /// opacity-weighted colour component, between any two values there (adaptive sampling's
    /// homogeneity). Unset: unknown, no region is homogeneous.
    std::function<std::function<double(double lo, double hi)>(const BindContext&)> variation = {};

    /// Whether this implementation may call `slot` (true when its calls are unknown).
    bool mayCall(const std::string& slot) const
    {
        return !traits.calls || std::find(traits.calls->begin(), traits.calls->end(), slot) != traits.calls->end();
    }
    /// Whether `slot` must be real when this implementation is chosen.
    bool requiresSlot(const std::string& slot) const
    {
        return std::find(traits.required.begin(), traits.required.end(), slot) != traits.required.end();
    }
};

}  // namespace volren
