#pragma once
// What `volren permutations --render` draws each composition into, and the checks a drawn
// composition must pass: the harness of the composition sweep.
#include <volume_renderer/Composition.h>
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/OffscreenRenderer.h>
#include <volume_renderer/VolumeScene.h>

#include <osg/Image>

#include <string>
#include <vector>

namespace volren::app {

/// A scene that gives every slot something to do: a float volume (a soft ball), a TF that shows
/// it, a light, one clip shape of every kind (plane, box, ellipsoid, mask; the opaque box that
/// crosses the volume is the depth clip's), so that every clip instance binds a real shape.
osg::ref_ptr<VolumeScene> sweepScene();

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

/// The checks of one frame of `composition`: `timing` as renderFrame() returned it (or
/// `thrown`, its exception's message: a compile or link error), `image` the frame (RGBA float),
/// `without` the same scene drawn without its volume (the opaque geometry over the background).
std::vector<SweepFailure> checkFrame(const Composition& composition, const FrameTiming& timing, const std::string& thrown,
                                     const osg::Image& image, const osg::Image& without, const SweepLimits& limits);

}  // namespace volren::app
