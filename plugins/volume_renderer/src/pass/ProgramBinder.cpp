#include "ProgramBinder.h"

#include <volume_renderer/SampleDistance.h>

namespace volren {

BindContext bindContextFor(const VolumeNode& node, osg::StateSet& stateSet, const ComposedProgram& program)
{
    return BindContext{.node = node,
                       .volume = *node.getVolume(),
                       .transfer = *node.getTransferFunction(),
                       .settings = node.settings,
                       .sampleDistance = effectiveSampleDistance(node),
                       .stateSet = stateSet,
                       .textureUnits = program.textureUnits,
                       .boxSize = node.getVolume()->worldSize()};
}

void bindProgram(BindContext& context, const ComposedProgram& program,
                 const std::map<std::string, std::vector<ClipInfo>>& clips, int member, TextureCache& textures,
                 unsigned int cull)
{
    std::vector<const Binding*> mine;
    for (const Binding& b : program.bindings)
        if (b.member == member) mine.push_back(&b);
    auto needs = [&](AuxData aux) {
        for (const Binding* b : mine)
            if (b->function->needsAux(aux)) return true;
        return false;
    };
    context.volumeTexture = [&textures, cull](const Volume& v, bool nearest) { return textures.volume(v, nearest, cull); };
    if (needs(AuxData::VolumeTexture)) context.aux[AuxData::VolumeTexture] = textures.volume(context.volume, false, cull);
    if (needs(AuxData::TransferFunctionTable))
        context.aux[AuxData::TransferFunctionTable] = textures.table(context.transfer, false, cull);
    if (needs(AuxData::PremultipliedTable))
        context.aux[AuxData::PremultipliedTable] = textures.table(context.transfer, true, cull);
    for (const Binding* b : mine)
        if (b->instance < 0) context.chosen[b->function->slot] = b->function->name;

    static const std::vector<ClipInfo> none;
    for (const Binding* b : mine) {
        if (!b->function->bind) continue;
        context.suffix = b->suffix;
        context.instance = b->instance;
        auto it = clips.find(b->function->slot);
        context.clips = it == clips.end() ? none : it->second;
        b->function->bind(context);
    }
}

}  // namespace volren
