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
    /// Auxiliary data made for this node, by kind name (AuxKind; ShaderFunction::needs).
    std::map<std::string, osg::ref_ptr<osg::Texture>> aux = {};
    std::vector<LightInfo> lights = {};  ///< lights reaching the volume
    std::vector<ClipInfo> clips = {};    ///< per template instance of the slot being bound
    std::string suffix = {};             ///< "_k" while binding template instance k, else ""
    int instance = -1;                   ///< k while binding template instance k, else -1
    std::map<std::string, std::string> chosen = {};  ///< slot -> implementation of this composition
    bool writesDepth = false;            ///< the composition's traversal reports surface hits
    /// Texture of a volume (shared per Volume); `nearest` selects nearest-voxel filtering.
    std::function<osg::Texture*(const Volume&, bool nearest)> volumeTexture = {};
    const BrickedVolume* bricks = nullptr;  ///< the volume's bricks when a composition needs the brick pool
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
    /// Volume texture space -> each light's geometry shadow map coordinates ([0,1]^2 and depth; a
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
