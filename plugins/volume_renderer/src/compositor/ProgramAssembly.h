#pragma once
// Internal to the compositor: the composed fragment source of one composition.
#include <volume_renderer/ShaderCompositor.h>
#include <volume_renderer/Slots.h>

#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace volren {

/// Builds the bindings, declarations and fragment source of one composition into `result`:
/// string 0 is the generated header and declarations, then the common files, then one string
/// per implementation (template instances renamed apart), then, for a multi-volume set, each
/// member's slots renamed by its suffix and the dispatchers over the members. When an
/// implementation has a build file, also the source of its compute program (one per member
/// with one, for a set).
class ProgramAssembly
{
public:
    ProgramAssembly(const ShaderFunctionRegistry& registry, const Composition& composition, ComposedProgram& result);
    /// Runs every step; returns the RaySetup (its vertex file is the program's vertex stage).
    const ShaderFunction* assemble();

private:
    using Sources = std::vector<std::pair<std::string, std::string>>;  ///< (name, text) in order
    const ShaderFunction* lookup(const std::string& slot, const std::string& name) const;
    void pick(const Composition& c, int member);
    /// Appends `binding` with the kinds of auxiliary data its implementation needs.
    void add(Binding binding);
    std::string declarations() const;
    std::string header() const;
    void append(const std::string& name, const std::string& text);
    std::string source(const ShaderFunction* f) const;
    std::string file(const std::string& relative) const;
    Sources slotSources(int member, const std::set<std::string>* only = nullptr) const;
    std::pair<std::string, std::string> templateSources(const SlotInfo& slot, const std::vector<const Binding*>& mine,
                                                        Sources& out) const;
    /// The names a set defines once, which members' sources keep unrenamed.
    std::set<std::string> memberSharedNames(const std::string& numerics) const;
    /// Each member's sources, renamed apart (but for _memberShared).
    void appendMembers(const std::string& slotDeclarations);
    void assembleBuild(const std::string& declarations, const std::string& numerics, const std::string& slotDeclarations);

    const ShaderFunctionRegistry& _registry;
    const Composition& _composition;
    ComposedProgram& _result;
    const ShaderFunction* _raySetup = nullptr;
    std::ostringstream _src;
    std::set<std::string> _memberShared;  ///< a set's: memberSharedNames(), computed once
    std::set<std::string> _memberMacros;  ///< macros each member has its own of (light count, defines)
};

}  // namespace volren
