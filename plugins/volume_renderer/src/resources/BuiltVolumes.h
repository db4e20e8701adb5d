#pragma once
// Internal to the pass: auxiliary volumes built on the GPU by a composition's build program
// (ShaderFunction::buildFile), one per VolumeNode and kind, rebuilt only when what they depend
// on changes.
#include <volume_renderer/AuxKind.h>
#include <volume_renderer/BindContext.h>
#include <volume_renderer/BuiltVolumeStatistics.h>

#include <osg/Node>
#include <osg/Program>
#include <osg/Texture3D>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace volren {

/// The GPU-built volumes of the nodes a pass draws.
class BuiltVolumes
{
public:
    BuiltVolumes();
    ~BuiltVolumes();
    /// The volume of built `kind` (AuxKind::build) of `node`: `dims` texels of `channels` half
    /// floats (1, 2 or 4), with the kind's mip chain and sampler state; remade when any of these
    /// change; used in cull `cull`.
    osg::Texture3D* texture(const VolumeNode* node, const AuxKind& kind, const osg::Vec3i& dims, int channels,
                            unsigned int cull);
    /// The volume of kind `kind` of `node` if texture() made one, else null.
    osg::Texture3D* find(const VolumeNode* node, const std::string& kind) const;
    /// The node that rebuilds `node`'s `kind` volume by running `plan` with `program` (culled
    /// under the ray caster's state so it reads the same uniforms and textures; the volume is
    /// image unit 1, its levels allocated when mip-mapped); null when the volume holds what
    /// `key` describes.
    osg::Node* build(const VolumeNode* node, const std::string& kind, const std::string& key, osg::Program* program,
                     std::vector<BuildDispatch> plan);
    /// Frees the volumes the last few cull traversals before `cull` did not use.
    void endCull(unsigned int cull);
    /// Volumes held.
    std::size_t count() const { return _entries.size(); }
    /// Bytes of texture storage held.
    std::size_t bytes() const;
    /// Statistics of the volumes used in cull `cull`.
    std::vector<BuiltVolumeStatistics> statistics(unsigned int cull) const;

private:
    struct Entry;
    std::map<std::pair<const VolumeNode*, std::string>, std::unique_ptr<Entry>> _entries;
};

}  // namespace volren
