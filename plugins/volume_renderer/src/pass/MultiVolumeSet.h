#pragma once
// Internal to the pass: the program and bindings of a multi-volume set.
#include "../resources/TextureCache.h"
#include "../resources/VolumeProxy.h"
#include "SceneAnalysis.h"

#include <volume_renderer/CompositionPolicy.h>

#include <vector>

namespace volren {

/// A volume of a multi-volume set, with its own composition.
struct SetMember
{
    const VolumeCandidate* candidate = nullptr;
    ChosenComposition chosen;
};

/// The bound of the members' boxes in the VolumeScene's axes: the set's box.
osg::BoundingBoxd setBound(const std::vector<SetMember>& members);

/// Builds `proxy` for the set of `members`: the policy's set composition over the members'
/// own, composed by `compositor` and bound with the set's box, the finest member step (in scene
/// units), the strictest early termination, and each member's slots, lights, clips and the map
/// from the set's texture space to its own; hidden when no member may show anything.
void updateSetProxy(VolumeProxy& proxy, std::vector<SetMember>& members, const CompositionPolicy& policy,
                    ShaderCompositor& compositor, TextureCache& textures, unsigned int cull);

}  // namespace volren
