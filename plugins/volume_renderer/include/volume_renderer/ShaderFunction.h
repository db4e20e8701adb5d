#pragma once
#include <osg/StateSet>
#include <osg/Texture>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace volren {

class Volume;
class VolumeNode;
class TransferFunction;
struct RenderSettings;

/// A uniform an implementation reads (the compositor declares it once in the program).
struct UniformDecl
{
    std::string name;      ///< GLSL name, `volren_` prefixed
    std::string glslType;  ///< "float", "vec2", "mat4", ...
};

/// A texture an implementation samples; the compositor gives each distinct name a unit.
struct TextureDecl
{
    std::string name;         ///< GLSL sampler name
    std::string samplerType;  ///< "sampler3D", "sampler1D", ...
};

/// Auxiliary data an implementation needs; the renderer creates only what a composition asks for.
enum class AuxData { VolumeTexture, TransferFunctionTable };

/// What an implementation may read and set while binding one volume for a frame.
struct BindContext
{
    const VolumeNode& node;              ///< the node being drawn
    const Volume& volume;                ///< its volume
    const TransferFunction& transfer;    ///< its transfer function
    const RenderSettings& settings;      ///< its settings
    double sampleDistance;               ///< effective step in world units
    osg::StateSet& stateSet;             ///< per-node state of the volume's proxy geometry
    const std::map<std::string, int>& textureUnits;  ///< sampler name -> unit, from the compositor
    std::map<AuxData, osg::ref_ptr<osg::Texture>> aux;  ///< auxiliary textures made for this node

    /// Sets uniform `name` to `value` on the node's state.
    template <typename T>
    void uniform(const std::string& name, const T& value)
    {
        osg::Uniform* u = stateSet.getUniform(name);
        if (!u) {
            u = new osg::Uniform(name.c_str(), value);
            stateSet.addUniform(u);
        } else {
            u->set(value);
        }
    }
    /// Binds `texture` to sampler `name` (its unit comes from the compositor).
    void texture(const std::string& name, osg::Texture* texture);
};

/// One implementation of a shader-function slot: a GLSL file plus what it needs.
/// The GLSL file states its slot and signature at the top and declares no uniforms itself:
/// the compositor emits the declarations listed here, once per program.
struct ShaderFunction
{
    std::string slot;                   ///< slot name, e.g. "RayTraversal"
    std::string name;                   ///< implementation name, e.g. "dvr_front_to_back"
    std::string file;                   ///< fragment source, relative to a shader directory
    std::string vertexFile;             ///< vertex source (RaySetup only), relative path
    std::vector<UniformDecl> uniforms;  ///< uniforms it reads
    std::vector<TextureDecl> textures;  ///< samplers it reads
    std::vector<AuxData> needs;         ///< auxiliary data the renderer must create
    std::function<void(BindContext&)> bind;  ///< sets this frame's uniform values and textures
};

}  // namespace volren
