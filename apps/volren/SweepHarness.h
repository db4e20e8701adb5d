#pragma once
// What `volren permutations --render` draws each composition into, and the checks a drawn
// composition must pass: the harness of the composition sweep.
#include <volume_renderer/Composition.h>
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/OffscreenRenderer.h>
#include <volume_renderer/VolumeScene.h>

#include <volume_reference/ReferenceSetup.h>

#include <osg/Image>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace volren::app {

/// The width and height of the sweep's frames, in pixels.
constexpr int sweepSize = 16;

/// A scene that gives every slot something to do: a float volume (a soft ball leaning along x,
/// 24x20x16 voxels of 0.5: no axis mirrors its gradients onto another), a TF that shows
/// it, a light, one clip shape of every kind (plane, box, ellipsoid, mask; the opaque box that
/// crosses the volume is the depth clip's), so that every clip instance binds a real shape.
osg::ref_ptr<VolumeScene> sweepScene();

/// Places `camera` for the sweep scene scaled by `scale` (perspective, 40 degrees, from
/// (20, -25, 15) x scale towards the origin, near 1 x scale, far 100 x scale).
void placeSweepCamera(osg::Camera& camera, double scale = 1.0);

/// The sweep scene as drawn: plain, or changed to one parameter extreme.
struct SweepVariant
{
    std::string name;  ///< empty: the plain sweep scene
    int width = sweepSize, height = sweepSize;
    bool showsVolume = true;  ///< false: nothing of the volume may show (the `drawn` check is off)
    /// Changes the sweep scene (and its placed camera) to this variant; null: none.
    std::function<void(VolumeScene& scene, osg::Camera& camera)> apply = {};
    /// The compositions that must refuse this scene with a clear error (a `compose` failure
    /// whose message holds one of `refusals`) instead of drawing it, judged on the scene as
    /// `apply` left it; null: none.
    std::function<bool(const Composition&, VolumeScene&)> refuses = {};
    std::vector<std::string> refusals = {};
    /// A known open defect this variant still shows (what fails, measured): it runs only when
    /// asked for by name (`--variant`), and a run without it says so.
    std::string openDefect = {};
};

/// The plain sweep scene, and with `extremes` the parameter extremes beside it: 8- and 16-bit
/// data, float values up to float's largest, NaN voxels, TF opacity 0 and 1, steps of 1/1000
/// and of 10 voxels, voxel spacings of 1e-9 and 1e12 (the whole scene scaled), a 1x1x1 and a
/// 4096x4x4 volume, the camera inside the volume, and 1x1 and 4096x4 viewports.
std::vector<SweepVariant> sweepVariants(bool extremes);

/// One failed check of a drawn composition.
struct SweepFailure
{
    std::string check;   ///< "compose", "link", "gl", "finite", "drawn", "time"
    std::string detail;  ///< what was measured, against what
};

/// Limits of the checks.
struct SweepLimits
{
    double frameMs = 30000.0;  ///< the longest a frame (compile and link included) may take
    bool drawn = true;         ///< the scene shows its volume (SweepVariant::showsVolume)
    /// Compositions that refuse the scene (SweepVariant::refuses): not drawn as variants.
    std::function<bool(const Composition&, VolumeScene&)> refuses = {};
};

/// A composition that must draw the same image as another, within `tolerance` (largest absolute
/// difference of any RGBA value).
struct Variant
{
    std::string check;     ///< "acceleration", "storage", "traversal"
    Composition composition;
    double tolerance = 0.0;
    bool withoutEarlyTermination = false;  ///< both drawn with early termination off
};

/// The metamorphic variants of `composition` (valid under `policy`), read from the registry's
/// declarations, not names: an exact skipping Acceleration (traits.skips, not approximates)
/// against none (bit-identical); every other real VolumeStorage (within 1e-4); every other
/// traversal that shares a ray as the same kind of emission-absorption (front-to-back against
/// back-to-front, early termination off, within 1e-4).
std::vector<Variant> variantsOf(const Composition& composition, const CompositionPolicy& policy);

/// The largest absolute difference of two RGBA float frames of one size (infinite where a value
/// is not finite in one of them).
double largestDifference(const osg::Image& a, const osg::Image& b);

/// Whether the sweep scene surely shows something of the volume under `composition`: where its
/// traversal composites emission-absorption (the TF, and the null classification's grey ramp,
/// give the ball opacity) and its ray setup, storage and reconstruction are real (a null
/// implementation does nothing observable). MIP, MinIP, average, isosurfaces and the other traversals may rightly show
/// nothing of this scene under some classifications; whether they should is the reference's to
/// say, not this check's.
bool showsVolume(const Composition& composition);

/// What the reference renderer says of a composition, from the ReferenceModel every
/// implementation it chooses declares (ordinary slots and each clip instance).
struct OracleBound
{
    bool modelled = false;  ///< every implementation declares a model, none Fidelity::None
    /// The largest absolute difference of any RGBA value from the reference it is held to: the
    /// sweep scene's own discretisation (oracleBase) plus each approximation's declared bound.
    double bound = 0.0;
    std::string why;  ///< not modelled: the first implementation without a model, and its reason
};

/// The difference an exact composition may show on the sweep scene at 16x16 against a converged
/// reference: float arithmetic, the TF table's resolution and the fixed step (half a voxel,
/// opacity-corrected) of the GPU. Measured over every modelled composition of the cover.
constexpr double oracleBase = 0.02;

/// The bound `composition` is held to against the reference, or why it is not compared.
OracleBound oracleBound(const Composition& composition);

/// Whether a factor value of the permutation space (PermutationSpace::ValueFilter) has a
/// reference model: each implementation it names declares one (not Fidelity::None).
bool modelledValue(const std::string& factor, const std::vector<std::string>& names);

/// The CPU reference of the sweep scene as each composition draws it (the chosen implementations'
/// lighting models and shadows, only the clip shapes its instances bind, the opaque geometry's
/// depth only where it clips rays by depth, no lights when it shades with none), cached by what
/// decides it: many compositions of a cover share one reference image.
class SweepOracle
{
public:
    /// Rasterises `scene`'s opaque geometry once for `camera`'s view (`width` x `height`).
    SweepOracle(VolumeScene& scene, const osg::Matrixd& view, const osg::Matrixd& projection, int width, int height,
                const osg::Vec3& background);
    /// The reference image of `composition` (modelled: oracleBound(composition).modelled).
    const ReferenceImage& image(const Composition& composition);
    /// The largest absolute difference of any RGBA value of `gpu` (RGBA float, same size) from
    /// the reference image (infinite where one is not finite).
    static double largestDifference(const osg::Image& gpu, const ReferenceImage& reference);
    /// Reference images computed so far (the rest came from the cache).
    std::size_t computed() const { return _cache.size(); }
    /// Seconds spent computing them.
    double seconds() const { return _seconds; }

private:
    const CompositionPolicy& _policy;
    ReferenceSetup _setup;
    ReferenceCamera _camera;
    std::map<std::string, ReferenceImage> _cache;
    double _seconds = 0.0;
};

/// The checks of one frame of `composition`: `timing` as renderFrame() returned it (or
/// `thrown`, its exception's message: a compile or link error), `image` the frame (RGBA float),
/// `without` the same scene drawn without its volume (the opaque geometry over the background).
std::vector<SweepFailure> checkFrame(const Composition& composition, const FrameTiming& timing, const std::string& thrown,
                                     const osg::Image& image, const osg::Image& without, const SweepLimits& limits);

}  // namespace volren::app
