#pragma once
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <osg/Program>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace volren {

/// What the scene asks of the ray caster: one implementation per ordinary slot, a list of
/// instances per template slot, and the number of lights.
struct Composition
{
    std::map<std::string, std::string> choice;                  ///< slot -> implementation
    std::map<std::string, std::vector<std::string>> instances;  ///< template slot -> one per shape
    unsigned int lightCount = 0;                                ///< lights the shading loops over
    /// A multi-volume set: one composition per member (their sample slots, clip planes and
    /// lights), marched along one ray by this composition's RayTraversal (`sum_of_media`).
    std::vector<Composition> members;

    /// Full key "Slot=impl;...;ClipPosition=[box,plane];lights=N;" over every slot, defaults
    /// filled in; programs are cached by the whole key.
    std::string key() const;
    /// Implementation for ordinary `slot` (its default when not chosen).
    std::string functionFor(const std::string& slot) const;
};

/// One implementation bound into a program: which one, and its template instance suffix.
struct Binding
{
    const ShaderFunction* function = nullptr;
    std::string suffix;  ///< "_k" for template instance k, else ""
    int instance = -1;   ///< k, or -1 for ordinary slots
    int member = -1;     ///< multi-volume sets: the member it belongs to, -1 for the set's own
    std::string memberSuffix;  ///< "_v<member>", or "" for the set's own (and single volumes)
};

/// A program for one composition, with what binding needs.
struct ComposedProgram
{
    std::string key;                          ///< Composition::key()
    osg::ref_ptr<osg::Program> program;       ///< vertex + composed fragment shader
    std::vector<Binding> bindings;            ///< every implementation in emission order
    std::map<std::string, int> textureUnits;  ///< sampler name -> texture unit
    std::string fragmentSource;               ///< the composed fragment source
    std::vector<std::string> sourceNames;     ///< GLSL source-string number -> file
    bool writesDepth = false;                 ///< the traversal reports surface hits
    /// Whether an implementation of this program needs `aux`.
    bool needs(AuxData aux) const;
};

/// Assembles one GLSL program per composition from shader-function files and caches it.
class ShaderCompositor
{
public:
    explicit ShaderCompositor(const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance());

    /// Program for `composition`, built on first use; throws std::runtime_error naming the
    /// slot and implementation when one is unknown, a file is missing, or declarations clash.
    std::shared_ptr<const ComposedProgram> program(const Composition& composition);

    /// Rewrites "N:line" references of a GLSL info log into "file:line".
    static std::string explainLog(const std::string& log, const ComposedProgram& program);

    /// Number of programs built so far (one per distinct composition).
    std::size_t programCount() const;
    /// The registry implementations come from.
    const ShaderFunctionRegistry& registry() const { return _registry; }

private:
    std::shared_ptr<const ComposedProgram> build(const Composition& composition) const;

    const ShaderFunctionRegistry& _registry;
    mutable std::mutex _mutex;
    std::map<std::string, std::shared_ptr<const ComposedProgram>> _cache;
};

}  // namespace volren
