#pragma once
#include <volume_renderer/ShaderCompositor.h>

#include <volume_model/VolumeNode.h>

#include <osg/Group>
#include <osg/NodeVisitor>
#include <osg/MatrixTransform>
#include <osg/Texture1D>
#include <osg/Texture3D>

#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace volren {

/// Root of a mixed scene and the pass that draws its volumes. Children are drawn as usual;
/// at cull time every VolumeNode below is found, its composition chosen from the scene, and
/// a ray-cast proxy (the volume's box, back faces) is drawn after the opaque geometry.
class VolumeScene : public osg::Group
{
public:
    VolumeScene();
    VolumeScene(const VolumeScene& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_Node(volren, VolumeScene)

    void traverse(osg::NodeVisitor& nv) override;

    /// Composition the scene analysis picks for `node` (what the node's settings ask for).
    static Composition chooseComposition(const VolumeNode& node);
    /// Step in world units for `node`: its setting, bounded so no ray exceeds maxSteps samples.
    static double effectiveSampleDistance(const VolumeNode& node);
    /// Most samples one ray may take; finer settings are coarsened to this, with a warning.
    static constexpr double maxSteps = double(1 << 22);

    /// Composition keys of the volumes drawn in the last cull traversal (sorted, unique).
    std::vector<std::string> compositionKeys() const;
    /// The compositor that builds this scene's programs.
    ShaderCompositor& compositor() { return _compositor; }
    /// Throws std::runtime_error with "file:line" messages if a program failed to compile or
    /// link in `state`'s context (call after a frame).
    void checkPrograms(osg::State& state) const;

protected:
    ~VolumeScene() override;

private:
    struct Proxy;
    struct VolumeGL;
    struct TransferGL;
    Proxy& updateProxy(VolumeNode& node);

    ShaderCompositor _compositor;
    mutable std::mutex _mutex;
    std::map<const VolumeNode*, Proxy> _proxies;
    std::map<const Volume*, VolumeGL> _volumeTextures;
    std::map<const TransferFunction*, TransferGL> _transferTextures;
    std::vector<std::string> _lastKeys;
    unsigned int _cullCount = 0;
};

}  // namespace volren
