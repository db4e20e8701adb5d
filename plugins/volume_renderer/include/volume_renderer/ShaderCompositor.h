#pragma once
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <osg/Program>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace volren {

/// The implementation chosen for each slot; slots not named use their default.
struct Composition
{
    std::map<std::string, std::string> choice;  ///< slot -> implementation name

    /// Full key "Slot=impl;..." over every slot (defaults filled in); compared in full.
    std::string key() const;
    /// Implementation for `slot` (the default when not chosen).
    std::string functionFor(const std::string& slot) const;
};

/// A linked-ready program for one composition, with what binding needs.
struct ComposedProgram
{
    std::string key;                                 ///< Composition::key()
    osg::ref_ptr<osg::Program> program;              ///< vertex + composed fragment shader
    std::vector<const ShaderFunction*> functions;    ///< one per slot, in slot order
    std::map<std::string, int> textureUnits;         ///< sampler name -> texture unit
    std::string fragmentSource;                      ///< the composed fragment source
    std::vector<std::string> sourceNames;            ///< GLSL source-string number -> file
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

private:
    std::shared_ptr<const ComposedProgram> build(const Composition& composition) const;

    const ShaderFunctionRegistry& _registry;
    mutable std::mutex _mutex;
    std::map<std::string, std::shared_ptr<const ComposedProgram>> _cache;
};

}  // namespace volren
