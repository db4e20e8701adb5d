#pragma once
#include <osgDB/Options>

#include <functional>

namespace volren {

/// Progress of a long load: called with the fraction done (0..1), now and then; returning
/// false cancels the load (the reader then fails with "cancelled").
using LoadProgress = std::function<bool(double fraction)>;

/// A copy of `base` (or new options) that carries `progress` to the volren readers. The
/// callback must outlive the read.
osg::ref_ptr<osgDB::Options> withLoadProgress(const osgDB::Options* base, const LoadProgress* progress);

/// The progress callback carried by `options`, or null.
const LoadProgress* loadProgressOf(const osgDB::Options* options);

/// Reports `done` of `total` units to the callback in `options` (if any); false when the
/// user cancelled. Cheap enough to call per slice or per megabyte.
bool reportLoadProgress(const osgDB::Options* options, double done, double total);

}  // namespace volren
