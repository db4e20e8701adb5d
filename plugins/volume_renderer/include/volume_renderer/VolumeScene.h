#pragma once
#include <volume_renderer/BrickPool.h>
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/BuiltVolumeStatistics.h>
#include <volume_renderer/PassSettings.h>
#include <volume_renderer/ShaderCompositor.h>

#include <volume_model/VolumeNode.h>

#include <osg/Group>
#include <osg/NodeVisitor>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace volren {

/// Root of a mixed scene and the pass that draws its volumes. Children are drawn as usual; at
/// cull time the pass analyses the scene (volumes, lights, clip shapes, opaque geometry), asks
/// the CompositionPolicy for each volume's composition and which volumes share a ray, and draws
/// a ray-cast proxy per volume (or per multi-volume set) after the opaque geometry, whose depth
/// ends the rays. Nothing a volume does not use is compiled, bound or allocated.
class VolumeScene : public osg::Group
{
public:
    VolumeScene();
    VolumeScene(const VolumeScene& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_Node(volren, VolumeScene)

    /// Settings every volume of the pass shares (lighting, slots forced null).
    PassSettings pass;
    /// When set, every volume gets exactly this composition instead of the policy's choice
    /// (permutation sweeps); template instances bind the offered clip shapes of their kind.
    std::optional<Composition> forcedComposition;

    void traverse(osg::NodeVisitor& nv) override;

    /// The policy that chooses this scene's compositions.
    const CompositionPolicy& policy() const { return _policy; }
    /// The compositor that builds this scene's programs.
    ShaderCompositor& compositor() { return _compositor; }

    /// Composition keys of the volumes and multi-volume sets drawn in the last cull traversal
    /// (sorted, unique).
    std::vector<std::string> compositionKeys() const;
    /// The program of each volume (or set: names joined by " + ") drawn in the last cull
    /// traversal, with the node's name.
    std::vector<std::pair<std::string, std::shared_ptr<const ComposedProgram>>> programs() const;
    /// Why volumes of the last cull traversal were not drawn (composing or binding threw), one
    /// message per volume naming it; empty when every volume was drawn (or hidden by its TF).
    std::vector<std::string> drawErrors() const;
    /// Throws std::runtime_error with "file:line" messages if a program drawn in the last cull
    /// traversal failed to compile or link in `state`'s context (call after a frame).
    void checkPrograms(osg::State& state) const;
    /// Auxiliary textures currently held (volumes, tables, screen textures): for tests of "only what is used".
    std::size_t auxiliaryTextureCount() const;
    /// Bytes of GL texture storage this scene holds (volumes, tables, screen textures): what the
    /// renderer allocates on the GPU besides the framebuffer.
    std::size_t textureBytes() const;
    /// Volumes and multi-volume sets the last cull traversal left undrawn because their occupancy
    /// grids show that no sample of theirs can be visible (a TF that hides everything).
    std::size_t hiddenVolumeCount() const;
    /// What each bricked volume the last cull traversal drew holds in its pool.
    std::vector<BrickStatistics> brickStatistics() const;
    /// Statistics of the auxiliary volumes built on the GPU (light volumes, opacity mip chains)
    /// the last cull used.
    std::vector<BuiltVolumeStatistics> builtVolumeStatistics() const;
    /// Depth maps of the opaque geometry drawn from the lights so far (for shadowing volumes;
    /// one per light and frame where its light, the geometry or a transform had changed).
    unsigned int geometryShadowMapDraws() const;
    /// Bricks the last cull traversal planned that are not in their pools yet (pass.streamBricks).
    std::size_t pendingBricks() const;
    /// Waits up to `seconds` for the brick loaders of the last cull traversal's volumes.
    void waitForBricks(double seconds) const;

protected:
    ~VolumeScene() override;

private:
    struct Pass;
    CompositionPolicy _policy;
    ShaderCompositor _compositor;
    mutable std::mutex _mutex;
    std::unique_ptr<Pass> _state;  ///< proxies, textures and screen passes, made at cull time
};

}  // namespace volren
