#pragma once
// What counts as opaque geometry next to volumes: drawn before them, mixed with them through
// its depth, and casting shadows on them (renderer and reference alike).
#include <osg/StateSet>

namespace volren {

/// Whether state `ss` puts what it applies to after the opaque bin (blended geometry, the
/// transparent bin or a later render bin): such drawables are not opaque geometry.
bool drawnAfterOpaque(const osg::StateSet* ss);

}  // namespace volren
