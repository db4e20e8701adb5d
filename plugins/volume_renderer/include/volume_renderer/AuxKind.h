#pragma once
// A kind of auxiliary data: what implementations list in ShaderFunction::needs, declared beside
// the implementations that use it (src/functions/<Slot>.cpp, or a plugin's registration). The
// pass makes only the kinds a composition needs and names none of them.
#include <osg/Matrixd>
#include <osg/Texture>
#include <osg/Vec3d>
#include <osg/Vec3i>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace osg {
class Geometry;
class StateSet;
}  // namespace osg
namespace osgUtil {
class CullVisitor;
}  // namespace osgUtil

namespace volren {

struct BindContext;
struct Binding;
struct ComposedProgram;
struct ShaderFunction;
class ScreenPasses;
class TextureCache;
class VolumeNode;

/// One compute dispatch of a build: integer uniforms set for it, then its work groups; every
/// dispatch's image writes are visible to the next. It writes mip level `level` of the volume
/// (image unit 1) and may read the level below (image unit 2, read-only) when `level` > 0.
struct BuildDispatch
{
    std::vector<std::pair<const char*, int>> uniforms;
    osg::Vec3i groups;
    int level = 0;
};

/// Where the pass makes a kind and who makes it.
enum class AuxScope
{
    Volume,             ///< per volume node as it is bound: AuxKind::provide, or the GPU AuxKind::build
    Camera,             ///< per camera as the volume is drawn: AuxKind::perCamera (screen-sized data)
    GeometryFromLights  ///< per scene before the frame: the opaque geometry's depth from each light
};

/// A volume built on the GPU by the composition's build program (ShaderFunction::buildFile, a
/// compute main writing image unit 1), one per node, rebuilt when what the build reads changes:
/// the program, the volume, the TF, the level, resident bricks, the values of the uniforms and
/// textures of the implementations it composes (lights only where `readsLights`).
struct AuxBuild
{
    std::string sampler = {};  ///< the sampler it is read through, left out of its own rebuild key
    bool readsLights = false;  ///< its contents depend on the lights (not only the classified volume)
    bool mipmapped = false;    ///< it has a full mip chain (allocated for the build to write)
    /// Outside the box: CLAMP_TO_EDGE repeats the edge texels, CLAMP_TO_BORDER reads zero.
    osg::Texture::WrapMode wrap = osg::Texture::CLAMP_TO_EDGE;
    /// Minification filter (LINEAR; LINEAR_MIPMAP_NEAREST reads a chain's nearest level).
    osg::Texture::FilterMode minFilter = osg::Texture::LINEAR;
    /// Its texels per axis for a sampled level of `levelDims` voxels (its shape and scale).
    std::function<osg::Vec3i(const osg::Vec3i& levelDims, const BindContext& context)> dims = {};
    /// Its half-float channels (1, 2 or 4: R16F, RG16F, RGBA16F).
    std::function<int(const BindContext& context)> channels = [](const BindContext&) { return 1; };
    /// The dispatches that build its `dims` texels over a box of `worldSize`.
    std::function<std::vector<BuildDispatch>(const BindContext& context, const osg::Vec3d& worldSize, const osg::Vec3i& dims)>
        plan = {};
};

/// What a Volume-scope provider sees while one volume (or set member) is bound.
struct AuxRequest
{
    BindContext& context;                         ///< the binding; a provider may refine its lod
    const std::vector<const Binding*>& bindings;  ///< the implementations bound for this volume
    TextureCache& textures;                       ///< the pass's texture caches (built-in kinds)
    unsigned int cull;                            ///< the cull traversal
    bool& anyVisible;  ///< set false where the data proves nothing of the volume is visible

    /// The implementation bound for `slot`, or null.
    const ShaderFunction* chosen(const std::string& slot) const;
};

/// What a Camera-scope provider sees as a volume's proxy is drawn for one camera.
struct AuxCameraRequest
{
    osgUtil::CullVisitor& cv;
    ScreenPasses& screen;            ///< the per-camera screen passes
    const ComposedProgram& program;  ///< the volume's program (its texture units)
    const VolumeNode* node;          ///< the volume drawn (a set's first member)
    osg::Geometry& box;              ///< its proxy geometry
    osg::Vec3d boxSize;              ///< the box the proxy draws
    osg::Matrixd matrix;             ///< volume -> world placement of the proxy
};

/// One kind of auxiliary data.
struct AuxKind
{
    std::string name;  ///< what ShaderFunction::needs lists, and statistics print ("light volume")
    AuxScope scope = AuxScope::Volume;
    /// Volume scope: the order kinds are made in, lower first (storage, which may refine the
    /// sampled level, before what is shaped by that level).
    int order = 1;
    /// Volume scope: makes (or finds in the pass's caches) the texture for the volume being bound.
    std::function<osg::Texture*(AuxRequest& request)> provide = {};
    /// Volume scope without `provide`: built on the GPU as this describes.
    std::optional<AuxBuild> build = {};
    /// Camera scope: the state set pushed while the proxy is drawn.
    std::function<osg::StateSet*(AuxCameraRequest& request)> perCamera = {};
    /// Its built volume holds each light's transmittance (one channel per light, as the light
    /// volume's layers): the pass darkens the opaque geometry inside the box by it.
    bool darkensGeometry = false;
};

}  // namespace volren
