#pragma once
#include <volume_renderer/Composition.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <osg/Program>

#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace volren {

/// One implementation bound into a program: which one, and its template instance suffix.
struct Binding
{
    const ShaderFunction* function = nullptr;
    std::string suffix;  ///< "_k" for template instance k, else ""
    int instance = -1;   ///< k, or -1 for ordinary slots
    int member = -1;     ///< multi-volume sets: the member it belongs to, -1 for the set's own
    std::string memberSuffix;  ///< "_v<member>", or "" for the set's own (and single volumes)
    /// The kinds of auxiliary data `function` needs, resolved once when the program is composed
    /// (composing throws for a kind no one declared), so binding and drawing look none up.
    std::vector<const AuxKind*> kinds = {};
};

/// The compute program that builds a volume's auxiliary data (ShaderFunction::buildFile).
struct BuildProgram
{
    osg::ref_ptr<osg::Program> program;   ///< the compute stage alone
    std::string source;                   ///< its composed source
    std::vector<std::string> sourceNames;  ///< GLSL source-string number -> file
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
    /// The compute programs of the implementations with a `buildFile`, by member (-1: a single
    /// volume's own; k: member k of a set); each shares the ray caster's uniform and sampler names.
    std::map<int, BuildProgram> builds;
    /// The build program of `member` (-1: a single volume), or null when it has none.
    const BuildProgram* build(int member) const;
};

/// Assembles one GLSL program per composition from shader-function files and caches it.
/// A program lives while a volume uses it; of the unused ones the most recently used
/// `cacheSize` are kept (switching settings back does not recompile) and older ones are
/// released, GL objects included, so a sweep over many compositions runs in bounded memory.
class ShaderCompositor
{
public:
    explicit ShaderCompositor(const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance());

    /// Program for `composition`, built on first use; throws std::runtime_error naming the
    /// slot and implementation when one is unknown, a file is missing, or declarations clash.
    std::shared_ptr<const ComposedProgram> program(const Composition& composition);

    /// Rewrites "N:line" references of a GLSL info log into "file:line".
    static std::string explainLog(const std::string& log, const ComposedProgram& program);
    /// The same for a program whose source strings are `sourceNames` (a build program's).
    static std::string explainLog(const std::string& log, const std::vector<std::string>& sourceNames);

    /// Number of programs held (in use or among the recently used).
    std::size_t programCount() const;
    /// Unused programs kept for reuse (default 8; 0 keeps only those in use).
    void setCacheSize(std::size_t programs);
    /// The registry implementations come from.
    const ShaderFunctionRegistry& registry() const { return _registry; }

private:
    std::shared_ptr<const ComposedProgram> build(const Composition& composition) const;
    void touch(const std::shared_ptr<const ComposedProgram>& program);

    const ShaderFunctionRegistry& _registry;
    mutable std::mutex _mutex;
    std::map<std::string, std::weak_ptr<const ComposedProgram>> _live;
    std::list<std::shared_ptr<const ComposedProgram>> _recent;  ///< most recent first
    std::size_t _cacheSize = 8;
};

}  // namespace volren
