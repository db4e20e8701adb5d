#include "GeometryShadows.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

namespace volren {

namespace {

/// Whether a lit implementation of `composition` (or of a set member) needs data the pass makes
/// from the opaque geometry seen from the lights (AuxScope::GeometryFromLights).
bool readsGeometryShadows(const Composition& composition, const ShaderFunctionRegistry& registry)
{
    if (composition.lightCount > 0)
        for (const auto& [slot, name] : composition.choice)
            if (const ShaderFunction* f = registry.find(slot, name))
                for (const AuxKind* kind : registry.auxKindsOf(*f))
                    if (kind->scope == AuxScope::GeometryFromLights) return true;
    for (const Composition& member : composition.members)
        if (readsGeometryShadows(member, registry)) return true;
    return false;
}

}  // namespace

void cullGeometryShadows(osgUtil::CullVisitor& cv, osg::Group& scene, std::vector<VolumeCandidate>& candidates,
                         const std::vector<ChosenComposition>& chosen, const ShaderFunctionRegistry& registry,
                         GeometryShadowMaps& maps)
{
    std::vector<std::size_t> readers;
    osg::BoundingBoxd receivers;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const VolumeCandidate& c = candidates[i];
        if (!c.offer.opaqueGeometry || c.offer.lights.empty() || !readsGeometryShadows(chosen[i].composition, registry)) continue;
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
