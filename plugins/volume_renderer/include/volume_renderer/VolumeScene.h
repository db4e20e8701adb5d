#pragma once
#include <volume_renderer/ScreenPasses.h>
#include <volume_renderer/ShaderCompositor.h>

#include <volume_model/VolumeNode.h>

#include <osg/Group>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>

#include <map>
#include <optional>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace volren {

/// What the scene offers one volume: its lights and the clip shapes that change it, in the
/// volume's own coordinates.
struct SceneOffer
{
    std::vector<LightInfo> lights;  ///< lights in the VolumeNode's local coordinates
    std::vector<ClipInfo> planes;   ///< clip planes that cut the volume
    std::vector<ClipInfo> shapes;   ///< other clip shapes (box, ellipsoid, mask) that change it
    bool opaqueGeometry = false;    ///< opaque polygons are drawn before the volumes
};

/// Root of a mixed scene and the pass that draws its volumes. Children are drawn as usual;
/// at cull time the scene is analysed (volumes, lights, clip shapes, opaque geometry), each
/// volume's composition is chosen, and a ray-cast proxy (the volume's box, back faces) is drawn
/// after the opaque geometry, whose depth ends the rays (ScreenPasses). Nothing a volume does
/// not use is compiled, bound or allocated.
/// Volumes whose boxes overlap form a multi-volume set when all of them composite
/// emission-absorption: one program for the set marches one ray through all of them, their
/// media adding where they overlap (Composition::members). Other volumes, and overlapping ones
/// with other traversals (MIP, isosurface, ...), are drawn box by box, sorted back to front.
class VolumeScene : public osg::Group
{
public:
    VolumeScene();
    VolumeScene(const VolumeScene& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_Node(volren, VolumeScene)

    /// Pass setting: when false the scene's lights are ignored (lighting slots become null).
    bool lighting = true;
    /// Pass setting: slots forced to null for every volume (testing, cost measurements).
    std::set<std::string> forceNull;
    /// When set, every volume gets exactly this composition instead of the analysed one
    /// (permutation sweeps; template instances without a matching clip shape bind nothing).
    std::optional<Composition> forcedComposition;

    void traverse(osg::NodeVisitor& nv) override;

    /// Sets a pass setting by name (`lighting`, `forceNull`); false with `error` set when the
    /// key is not a pass setting or the value is bad.
    bool set(const std::string& key, const std::string& value, std::string& error);
    /// Pass setting names with one-line descriptions.
    static std::vector<std::pair<std::string, std::string>> keys();
    /// Current value of pass setting `key` as text.
    std::string get(const std::string& key) const;

    /// The composition for `node` given what the scene offers it and the pass settings.
    Composition chooseComposition(const VolumeNode& node, const SceneOffer& offer) const;
    /// Whether a volume drawn with `composition` can share a ray with overlapping volumes
    /// (emission-absorption traversals).
    static bool canShareRay(const Composition& composition);
    /// Step in world units for `node`: its setting, bounded so no ray exceeds maxSteps samples.
    static double effectiveSampleDistance(const VolumeNode& node);
    /// Most samples one ray may take; finer settings are coarsened to this, with a warning.
    static constexpr double maxSteps = double(1 << 22);
    /// Largest number of lights passed to one volume (more are ignored, with a warning).
    static constexpr unsigned int maxLights = 8;

    /// Composition keys of the volumes and multi-volume sets drawn in the last cull traversal
    /// (sorted, unique).
    std::vector<std::string> compositionKeys() const;
    /// The program of each volume (or set: names joined by " + ") drawn in the last cull
    /// traversal, with the node's name.
    std::vector<std::pair<std::string, std::shared_ptr<const ComposedProgram>>> programs() const;
    /// The compositor that builds this scene's programs.
    ShaderCompositor& compositor() { return _compositor; }
    /// Throws std::runtime_error with "file:line" messages if a program failed to compile or
    /// link in `state`'s context (call after a frame).
    void checkPrograms(osg::State& state) const;
    /// Auxiliary textures currently held (volumes, tables): for tests of "only what is used".
    std::size_t auxiliaryTextureCount() const;
    /// Bytes of GL texture storage this scene holds (volumes, tables, screen textures): what the
    /// renderer allocates on the GPU besides the framebuffer.
    std::size_t textureBytes() const;

protected:
    ~VolumeScene() override;

private:
    struct Proxy;
    struct VolumeGL;
    struct TableGL;
    struct Candidate;
    Proxy& updateProxy(VolumeNode& node, const SceneOffer& offer, const Composition& composition);
    Proxy& updateSetProxy(const std::vector<const Candidate*>& members);
    /// Binds the parts of `program` that belong to `member` (-1: a single volume, or a set's own).
    void bind(BindContext& context, const ComposedProgram& program, const SceneOffer& offer, int member);
    Proxy& proxyGeometry(Proxy& proxy, const osg::Vec3d& boxSize, const ComposedProgram& program);
    osg::Texture* volumeTexture(const Volume& volume, bool nearest);

    ShaderCompositor _compositor;
    ScreenPasses _screen;
    mutable std::mutex _mutex;
    std::map<const VolumeNode*, Proxy> _proxies;
    std::map<std::vector<const VolumeNode*>, Proxy> _sets;  ///< multi-volume sets, by member
    std::set<std::vector<const VolumeNode*>> _warnedOverlaps;
    std::map<std::pair<const Volume*, bool>, VolumeGL> _volumeTextures;
    std::map<std::pair<const TransferFunction*, bool>, TableGL> _tables;
    std::vector<std::string> _lastKeys;
    unsigned int _cullCount = 0;
};

}  // namespace volren
