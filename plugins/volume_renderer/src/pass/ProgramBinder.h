#pragma once
// Internal to the pass: binding a composed program's implementations for one frame.
#include "../resources/TextureCache.h"
#include "SceneAnalysis.h"

#include <volume_renderer/ShaderCompositor.h>

#include <volume_model/VolumeNode.h>

#include <map>
#include <string>
#include <vector>

namespace volren {

/// The context that binds `program` for the candidate's node into `stateSet`: the node, its
/// volume, TF, settings, mip level and step (2^lod times the node's), the driver's filtering,
/// the volume's own box; lights, clips and member data are the caller's.
BindContext bindContextFor(const VolumeCandidate& candidate, osg::StateSet& stateSet, const ComposedProgram& program);

/// Binds the implementations of `program` that belong to `member` (-1: a single volume, or a
/// set's own) into `context`: first the auxiliary data they ask for (only that), then each
/// implementation's bind, template instances with their clip from `clips` (slot -> one per
/// instance). Textures come from `textures`, marked used in cull `cull`. Returns false when a
/// bound occupancy grid shows that no sample of the member can be visible (nothing to draw).
bool bindProgram(BindContext& context, const ComposedProgram& program,
                 const std::map<std::string, std::vector<ClipInfo>>& clips, int member, TextureCache& textures,
                 unsigned int cull);

}  // namespace volren
