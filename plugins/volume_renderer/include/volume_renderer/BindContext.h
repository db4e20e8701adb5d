#pragma once
#include <osg/Matrixd>
#include <osg/Matrixf>
#include <osg/Node>

#include <optional>
#include <osg/StateSet>
#include <osg/Texture>
#include <osg/Vec4d>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace volren {

class ClipNode;
class Volume;
class VolumeNode;
class TransferFunction;
struct RenderSettings;

/// Auxiliary data an implementation needs; the renderer creates only what a composition asks for.
/// The screen-sized ones are per camera and bound by the pass itself (VolumeScene):
/// - DepthTexture: the depth of the opaque geometry drawn before the volumes, as sampler2D
///   `volren_depthTexture` read with texelFetch at gl_FragCoord.xy - `volren_viewportOrigin`;
/// - EntryPoints: the volume-space points of the box's rasterised front faces, as image2D
///   `volren_entryPoints` (rgba32f: xyz, w = `volren_frameStamp` of the frame that wrote it).
/// - OccupancyGrid: per macrocell of the volume, whether any sample in it may be visible under
///   the current transfer function (MacrocellGrid.h), as an R8 3D texture read with texelFetch;
/// - MacrocellRanges: per macrocell the smallest and largest texel value its samples can read,
///   as an RG16F 3D texture (bounds rounded outwards) read with texelFetch (MacrocellGrid.h);
/// - HomogeneityGrid: the OccupancyGrid with visible cells told apart: 255 where the
///   classification varies by at most the node's adaptiveTolerance over the cell's values
///   (Classification's `variation` mirror), else 128 (adaptive sampling).
/// - BrickPool: the volume's mip levels in bricks in a pool texture with their page table
///   (BrickPool.h; VolumeStorage bricked), within the node's memory budget.
/// - LightVolume: per node, each light's transmittance (one half-float channel per light, up to
///   four) over the volume's box at lightVolumeScale of its resolution, built on the GPU by the
///   implementation's build program (ShaderFunction::buildFile) when what it depends on changes.
/// - OpacityMipChain: per node, the classified extinction (per world unit) at every voxel of the
///   sampled level, as a half-float 3D texture with a full mip chain (box-filtered on the GPU,
///   zero outside the box), built by the implementation's build program when the TF, the volume
///   or a clip shape changes (cone tracing).
/// - GeometryShadowMap: per scene, the depth of its opaque geometry seen from each light (up to
///   four; a 2D array texture compared LEQUAL, one layer per light) over the boxes of the
///   volumes that read it, drawn before the frame by the pass; with
///   BindContext::geometryShadowMatrices (shadowing methods: polygons shadow volumes).
enum class AuxData
{
    VolumeTexture,
    TransferFunctionTable,
    PremultipliedTable,
    JitterTexture,
    DepthTexture,
    EntryPoints,
    OccupancyGrid,
    MacrocellRanges,
    HomogeneityGrid,
    BrickPool,
    LightVolume,
    OpacityMipChain,
    GeometryShadowMap
};

struct BrickedVolume;

/// A light as the volume sees it, in the VolumeNode's local coordinates.
struct LightInfo
{
    osg::Vec4d position;  ///< w = 0: direction towards the light; w = 1: point light position
    osg::Vec3d colour;    ///< diffuse colour of the osg::Light
};

/// A clip shape as the volume sees it.
struct ClipInfo
{
    const ClipNode* node = nullptr;  ///< the shape
    osg::Matrixd textureToShape;     ///< volume texture space -> the shape's local coordinates
};

/// What an implementation may read and set while binding one volume for a frame. Built with
/// named fields (`BindContext{.node = n, .volume = v, ...}`); the pass fills the per-binding ones.
struct BindContext
{
    const VolumeNode& node;              ///< the node being drawn
    const Volume& volume;                ///< its volume
    const TransferFunction& transfer;    ///< its transfer function
    const RenderSettings& settings;      ///< its settings
    double sampleDistance = 0.0;         ///< effective step in world units (2^lod times the node's)
    int lod = 0;                         ///< mip level the volume is sampled from (level of detail)
    bool coarseByteFiltering = false;    ///< the driver filters 8-bit textures to 8-bit results
    osg::StateSet& stateSet;             ///< per-node state of the volume's proxy geometry
    const std::map<std::string, int>& textureUnits;  ///< sampler name -> unit, from the compositor
    std::map<AuxData, osg::ref_ptr<osg::Texture>> aux = {};  ///< auxiliary textures made for this node
    std::vector<LightInfo> lights = {};  ///< lights reaching the volume
    std::vector<ClipInfo> clips = {};    ///< per template instance of the slot being bound
    std::string suffix = {};             ///< "_k" while binding template instance k, else ""
    int instance = -1;                   ///< k while binding template instance k, else -1
    std::map<std::string, std::string> chosen = {};  ///< slot -> implementation of this composition
    bool writesDepth = false;            ///< the composition's traversal reports surface hits
    /// Texture of a volume (shared per Volume); `nearest` selects nearest-voxel filtering.
    std::function<osg::Texture*(const Volume&, bool nearest)> volumeTexture = {};
    const BrickedVolume* bricks = nullptr;  ///< the volume's bricks when a composition asks for BrickPool
    /// Volume texture space -> clip space of the camera culling it (bricks outside are not loaded).
    std::optional<osg::Matrixd> textureToClip = {};
    /// Size of the box the proxy draws; zero means the volume's own box (a multi-volume set's
    /// program draws the union of its members' boxes).
    osg::Vec3d boxSize = {};
    /// "_v<k>" while binding member k of a multi-volume set, else "" (added after `suffix`).
    std::string member = {};
    /// Multi-volume sets: the set box's texture space -> this member's texture space.
    osg::Matrixd setToMember = {};
    /// GPU builds of auxiliary data to draw before the ray caster, under its state.
    std::vector<osg::ref_ptr<osg::Node>> prepasses = {};
    /// Volume texture space -> each light's GeometryShadowMap coordinates ([0,1]^2 and depth; a
    /// zero matrix where no map covers that light). Empty: no opaque geometry shadows the volume.
    std::vector<osg::Matrixd> geometryShadowMatrices = {};

    /// Name of `base` for the instance being bound (adds the template and member suffixes).
    std::string name(const std::string& base) const { return base + suffix + member; }
    /// Runs `bind(*this)` with the template suffix off, for uniforms declared `shared` (a
    /// multi-volume member keeps its member suffix).
    template <typename F>
    void unsuffixed(F bind)
    {
        const std::string saved = suffix;
        suffix.clear();
        bind(*this);
        suffix = saved;
    }
    /// The clip shape of the template instance being bound (an empty one when it has none).
    const ClipInfo& clip() const;

    /// Sets uniform `name` (template suffix added) to `value` on the node's state.
    template <typename T>
    void uniform(const std::string& base, const T& value)
    {
        const std::string full = name(base);
        osg::Uniform* u = stateSet.getUniform(full);
        if (!u) {
            u = new osg::Uniform(full.c_str(), value);
            stateSet.addUniform(u);
        } else {
            u->set(value);
        }
    }
    /// Sets element `index` of uniform array `base` (of `size` elements) to `value`.
    template <typename T>
    void uniformElement(const std::string& base, unsigned int size, unsigned int index, const T& value)
    {
        const std::string full = name(base);
        osg::Uniform* u = stateSet.getUniform(full);
        if (!u || u->getNumElements() != size) {
            if (u) stateSet.removeUniform(u);
            u = new osg::Uniform(osg::Uniform::getTypeId(glslTypeOf(value)), full, int(size));
            stateSet.addUniform(u);
        }
        u->setElement(index, value);
    }
    /// Binds `texture` to sampler `base` (template suffix added; unit from the compositor).
    void texture(const std::string& base, osg::Texture* texture);

private:
    static std::string glslTypeOf(float) { return "float"; }
    static std::string glslTypeOf(const osg::Vec3f&) { return "vec3"; }
    static std::string glslTypeOf(const osg::Vec4f&) { return "vec4"; }
    static std::string glslTypeOf(const osg::Matrixf&) { return "mat4"; }
};

}  // namespace volren
