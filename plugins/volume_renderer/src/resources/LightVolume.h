#pragma once
// Internal to the pass: propagated light volumes (Shadowing light_volume), one per VolumeNode,
// built on the GPU by the composition's build program and rebuilt only when what they depend
// on changes.
#include <volume_renderer/BindContext.h>
#include <volume_renderer/LightVolumeStatistics.h>

#include <osg/Node>
#include <osg/Program>
#include <osg/Texture3D>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace volren {


/// The texels per axis of the light volume of a volume of `dims` voxels at `scale` (0, 1]:
/// each axis scaled and rounded, at least 2.
osg::Vec3i lightVolumeDims(const osg::Vec3i& dims, double scale);

/// The light volumes of the nodes a pass draws.
class LightVolumes
{
public:
    LightVolumes();
    ~LightVolumes();
    /// The light-volume texture of `node` with `dims` texels and one half-float channel per light
    /// (up to four: R16F, RG16F or RGBA16F), remade when either changes; used in cull `cull`.
    osg::Texture3D* texture(const VolumeNode* node, const osg::Vec3i& dims, int lights, unsigned int cull);
    /// The node that rebuilds `node`'s light volume with `program` (a build program, culled under
    /// the ray caster's state so it reads the same uniforms and textures) for `lights` in the
    /// node's local coordinates over a box of `worldSize`; null when the volume already holds
    /// what `key` (everything the build depends on) describes.
    osg::Node* build(const VolumeNode* node, const std::string& key, osg::Program* program,
                     const std::vector<LightInfo>& lights, const osg::Vec3d& worldSize);
    /// Frees the light volumes the last few cull traversals before `cull` did not use.
    void endCull(unsigned int cull);
    /// Light volumes held.
    std::size_t count() const { return _entries.size(); }
    /// Bytes of texture storage held.
    std::size_t bytes() const;
    /// Statistics of the light volumes used in cull `cull`.
    std::vector<LightVolumeStatistics> statistics(unsigned int cull) const;

private:
    struct Entry;
    std::map<const VolumeNode*, std::unique_ptr<Entry>> _entries;
};

}  // namespace volren
