#include "MultiVolumeSet.h"
#include "ProgramBinder.h"

#include <volume_renderer/SampleDistance.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace volren {

osg::BoundingBoxd setBound(const std::vector<SetMember>& members)
{
    osg::BoundingBoxd bound;
    for (const SetMember& m : members) bound.expandBy(m.candidate->bound);
    return bound;
}

void updateSetProxy(VolumeProxy& proxy, std::vector<SetMember>& members, const CompositionPolicy& policy,
                    ShaderCompositor& compositor, TextureCache& textures, unsigned int cull)
{
    const osg::BoundingBoxd bound = setBound(members);
    const osg::Vec3d size = bound._max - bound._min;
    const osg::Matrixd setTextureToScene =
        osg::Matrixd::translate(-0.5, -0.5, -0.5) * osg::Matrixd::scale(size) * osg::Matrixd::translate(bound.center());

    std::vector<ChosenComposition> parts;
    for (const SetMember& m : members) parts.push_back(m.chosen);
    const ChosenComposition set = policy.setComposition(parts);
    std::shared_ptr<const ComposedProgram> program = compositor.program(set.composition);
    osg::StateSet& ss = proxy.update(size, program);

    double step = std::numeric_limits<double>::infinity();
    double threshold = 1.0;
    for (const SetMember& m : members) {
        const osg::Vec3d scale = m.candidate->matrix.getScale();  // member-local steps in scene units
        step = std::min(step, std::ldexp(effectiveSampleDistance(*m.candidate->node), m.candidate->lod) *
                                  std::min({scale.x(), scale.y(), scale.z()}));
        threshold = std::min(threshold, m.candidate->node->settings.earlyTerminationThreshold);
    }
    const VolumeNode& first = *members.front().candidate->node;
    RenderSettings setSettings = first.settings;
    setSettings.earlyTerminationThreshold = threshold;
    BindContext setContext{.node = first,
                           .volume = *first.getVolume(),
                           .transfer = *first.getTransferFunction(),
                           .settings = setSettings,
                           .sampleDistance = step,
                           .stateSet = ss,
                           .textureUnits = program->textureUnits,
                           .boxSize = size};  // the set's box, step and termination
    bindProgram(setContext, *program, set.clips, -1, textures, cull);
    proxy.hidden = true;  // until a member may show something
    proxy.prepasses.clear();  // the members' builds of auxiliary volumes
    for (std::size_t k = 0; k < members.size(); ++k) {
        const VolumeCandidate& c = *members[k].candidate;
        const Volume& volume = *c.node->getVolume();
        const osg::Matrixd memberTextureToScene = textureToLocal(volume) * c.matrix;
        BindContext context = bindContextFor(c, ss, *program);
        context.lights = c.offer.lights;
        context.member = "_v" + std::to_string(k);
        context.setToMember = setTextureToScene * osg::Matrixd::inverse(memberTextureToScene);
        if (bindProgram(context, *program, parts[k].clips, int(k), textures, cull)) proxy.hidden = false;
        for (osg::ref_ptr<osg::Node>& build : context.prepasses) proxy.prepasses.push_back(std::move(build));
    }
}

}  // namespace volren
