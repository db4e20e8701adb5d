#include "GeometryShadows.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

namespace {

/// Whether the Shadowing of `composition` (or of a set member) reads the geometry shadow maps.
bool readsGeometryShadows(const Composition& composition)
{
    if (composition.geometryShadows) return true;
    for (const Composition& member : composition.members)
        if (readsGeometryShadows(member)) return true;
    return false;
}

}  // namespace

void cullGeometryShadows(osgUtil::CullVisitor& cv, osg::Group& scene, std::vector<VolumeCandidate>& candidates,
                         const std::vector<ChosenComposition>& chosen, GeometryShadowMaps& maps)
{
    std::vector<std::size_t> readers;
    osg::BoundingBoxd receivers;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const VolumeCandidate& c = candidates[i];
        if (!c.offer.opaqueGeometry || c.offer.lights.empty() || !readsGeometryShadows(chosen[i].composition)) continue;
        readers.push_back(i);
        receivers.expandBy(c.bound);
    }
    if (readers.empty()) return;
    maps.cull(cv, scene, candidates[readers.front()].sceneLights, receivers);
    for (std::size_t i : readers) {
        VolumeCandidate& c = candidates[i];
        const osg::Matrixd textureToScene = textureToLocal(*c.node->getVolume()) * c.matrix;
        c.geometryShadowMatrices.clear();
        for (const osg::Matrixd& m : maps.matrices()) c.geometryShadowMatrices.push_back(textureToScene * m);
        c.geometryShadowMap = maps.texture();
    }
}

}  // namespace volren
