#pragma once
// Internal to the pass: auxiliary volumes built on the GPU by a composition's build program
// (ShaderFunction::buildFile), one per VolumeNode and kind, rebuilt only when what they depend
// on changes.
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

/// One compute dispatch of a build: integer uniforms set for it, then its work groups; every
/// dispatch's image writes are visible to the next. It writes mip level `level` of the volume
/// (image unit 1) and may read the level below (image unit 2, read-only) when `level` > 0.
struct BuildDispatch
{
    std::vector<std::pair<const char*, int>> uniforms;
    osg::Vec3i groups;
    int level = 0;
};

/// The GPU-built volumes of the nodes a pass draws.
class BuiltVolumes
{
public:
    BuiltVolumes();
    ~BuiltVolumes();
    /// The `kind` volume of `node`: `dims` texels of `channels` half floats (1, 2 or 4), with a
    /// full mip chain when `mipmapped`; remade when any of these change; used in cull `cull`.
    osg::Texture3D* texture(const VolumeNode* node, AuxData kind, const osg::Vec3i& dims, int channels, bool mipmapped,
                            unsigned int cull);
    /// The `kind` volume of `node` if texture() made one, else null.
    osg::Texture3D* find(const VolumeNode* node, AuxData kind) const;
    /// The node that rebuilds `node`'s `kind` volume by running `plan` with `program` (culled
    /// under the ray caster's state so it reads the same uniforms and textures; the volume is
    /// image unit 1, its levels allocated when mip-mapped); null when the volume holds what
    /// `key` describes.
    osg::Node* build(const VolumeNode* node, AuxData kind, const std::string& key, osg::Program* program,
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
    std::map<std::pair<const VolumeNode*, AuxData>, std::unique_ptr<Entry>> _entries;
};

}  // namespace volren
