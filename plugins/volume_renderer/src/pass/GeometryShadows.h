#pragma once
// Internal to the pass: which volumes read the opaque geometry's shadow maps, and the maps
// culled for them.
#include "SceneAnalysis.h"

#include "../resources/GeometryShadowMaps.h"

#include <vector>

namespace volren {

/// Culls `maps` for the lights of the `candidates` whose `chosen` Shadowing reads them (lit, in
/// a scene with opaque geometry), over their boxes, and gives each of those its matrices and the
/// maps' texture (VolumeCandidate::geometryShadowMatrices, geometryShadowMap).
void cullGeometryShadows(osgUtil::CullVisitor& cv, osg::Group& scene, std::vector<VolumeCandidate>& candidates,
                         const std::vector<ChosenComposition>& chosen, const ShaderFunctionRegistry& registry,
                         GeometryShadowMaps& maps);

}  // namespace volren
