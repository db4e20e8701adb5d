#include "ProgramAssembly.h"
#include "BuildSlots.h"
#include "GlslRewriting.h"

#include <volume_renderer/Slots.h>

#include <algorithm>
#include <map>
#include <regex>
#include <stdexcept>

namespace volren {

namespace {

const char* const glslVersion = "#version 430 core\n";

}  // namespace

ProgramAssembly::ProgramAssembly(const ShaderFunctionRegistry& registry, const Composition& composition,
                                 ComposedProgram& result)
    : _registry(registry), _composition(composition), _result(result)
{
}

const ShaderFunction* ProgramAssembly::lookup(const std::string& slot, const std::string& name) const
{
    const ShaderFunction* f = _registry.find(slot, name);
    if (!f) {
        std::string known;
        for (const auto& n : _registry.names(slot)) known += (known.empty() ? "" : ", ") + n;
        throw std::runtime_error("slot " + slot + ": no implementation '" + name + "' (known: " + known + ")");
    }
    return f;
}

void ProgramAssembly::pick(const Composition& c, int member)
{
    // One implementation per ordinary slot, one per instance of template slots; for a
    // multi-volume set, the set's own and then every member's (with the member's suffix).
    const std::string memberSuffix = member < 0 ? "" : "_v" + std::to_string(member);
    for (const SlotInfo& s : slots()) {
        if (s.isTemplate) {
            const std::vector<std::string>& names = c.instancesOf(s.name);
            for (std::size_t k = 0; k < names.size(); ++k)
                add({lookup(s.name, names[k]), "_" + std::to_string(k), int(k), member, memberSuffix});
            continue;
        }
        const ShaderFunction* f = lookup(s.name, c.functionFor(s.name));
        if (f->traits.multiVolume != (member < 0 && !_composition.members.empty()) && s.name == "RayTraversal")
            throw std::runtime_error("slot RayTraversal: '" + f->name + "' " +
                                     (f->traits.multiVolume ? "only marches a multi-volume set"
                                                            : "cannot march a multi-volume set"));
        add({f, "", -1, member, memberSuffix});
        if (member >= 0) continue;
        if (s.name == "RaySetup") _raySetup = f;
        if (s.name == "RayTraversal") _result.writesDepth = f->traits.writesDepth;
    }
    if (member >= 0) add({lookup("MultiVolume", "member"), "", -1, member, memberSuffix});
}

void ProgramAssembly::add(Binding binding)
{
    binding.kinds = _registry.auxKindsOf(*binding.function);
    _result.bindings.push_back(std::move(binding));
}

std::string ProgramAssembly::declarations() const
{
    // Each uniform and sampler once; a clash in type is an error naming both.
    std::map<std::string, std::pair<std::string, const ShaderFunction*>> declared;
    std::ostringstream decls;
    auto declare = [&](const std::string& name, const std::string& type, const ShaderFunction* owner) {
        auto [it, inserted] = declared.emplace(name, std::make_pair(type, owner));
        if (!inserted && it->second.first != type)
            throw std::runtime_error("uniform '" + name + "' declared as " + it->second.first + " by " +
                                     it->second.second->slot + "/" + it->second.second->name + " and as " + type +
                                     " by " + owner->slot + "/" + owner->name);
        if (inserted) decls << "uniform " << type << " " << name << ";  // " << owner->slot << "/" << owner->name << "\n";
    };
    int nextUnit = 0;
    for (const Binding& b : _result.bindings) {
        for (const TextureDecl& t : b.function->textures) {
            const std::string name = (t.shared ? t.name : t.name + b.suffix) + b.memberSuffix;
            if (!_result.textureUnits.count(name)) _result.textureUnits[name] = nextUnit++;
            declare(name, t.samplerType, b.function);
        }
        for (const UniformDecl& u : b.function->uniforms) {
            const std::string name = (u.shared ? u.name : u.name + b.suffix) + b.memberSuffix;
            const std::string size = u.arraySize.rfind("VOLREN_", 0) == 0 ? u.arraySize + b.memberSuffix : u.arraySize;
            declare(size.empty() ? name : name + "[" + size + "]", u.glslType, b.function);
        }
    }
    return decls.str();
}

std::string ProgramAssembly::header() const
{
    std::ostringstream src;
    src << glslVersion;
    src << "// volren composed ray caster: " << _result.key << "\n";
    src << "#define VOLREN_LIGHT_COUNT " << _composition.lightCount << "\n";
    src << "#define VOLREN_LIGHT_ARRAY " << std::max(1u, _composition.lightCount) << "\n";
    // The chosen implementations' macros, each once: the hooks' values, else the declared defaults.
    auto defines = [&](const Composition& c, int member, const std::string& suffix) {
        std::set<std::string> done;
        for (const Binding& b : _result.bindings) {
            if (b.member != member) continue;
            for (const auto& [name, value] : b.function->defines) {
                if (!done.insert(name).second) continue;
                auto set = c.defines.find(name);
                src << "#define " << name << suffix << " " << (set == c.defines.end() ? value : set->second) << "\n";
            }
        }
    };
    defines(_composition, -1, "");
    // Macros the pass sets for the whole program, which no implementation declares
    // (PassSettings::countSamples: VOLREN_COUNT_SAMPLES).
    std::set<std::string> declared;
    for (const Binding& b : _result.bindings)
        for (const auto& define : b.function->defines) declared.insert(define.first);
    for (const auto& [name, value] : _composition.defines)
        if (!declared.count(name)) src << "#define " << name << " " << value << "\n";
    if (!_composition.members.empty()) src << "#define VOLREN_MEMBER_COUNT " << _composition.members.size() << "\n";
    for (std::size_t k = 0; k < _composition.members.size(); ++k) {
        const unsigned int lights = _composition.members[k].lightCount;
        src << "#define VOLREN_LIGHT_COUNT_v" << k << " " << lights << "\n";
        src << "#define VOLREN_LIGHT_ARRAY_v" << k << " " << std::max(1u, lights) << "\n";
        defines(_composition.members[k], int(k), "_v" + std::to_string(k));
    }
    return src.str();
}

void ProgramAssembly::append(const std::string& name, const std::string& text)
{
    const int index = int(_result.sourceNames.size());
    _result.sourceNames.push_back(name);
    _src << "// ---- " << name << " ----\n#line 1 " << index << "\n" << text << "\n";
}

std::string ProgramAssembly::file(const std::string& relative) const
{
    return _registry.read(relative);
}

std::string ProgramAssembly::source(const ShaderFunction* f) const
{
    try {
        return file(f->file);
    } catch (const std::exception& e) {
        throw std::runtime_error("slot " + f->slot + ", implementation " + f->name + ": " + e.what());
    }
}

ProgramAssembly::Sources ProgramAssembly::slotSources(int member, const std::set<std::string>* only) const
{
    // The slots of the set's own composition (member < 0), or of one member; only those in
    // `only` when given.
    Sources out;
    std::set<std::string> included;
    for (const SlotInfo& s : slots()) {
        if (member >= 0 && s.perSet) continue;
        if (only && !only->count(s.name)) continue;
        std::vector<const Binding*> mine;
        for (const Binding& b : _result.bindings)
            if (b.member == member && b.function->slot == s.name) mine.push_back(&b);
        if (s.isTemplate) {
            auto dispatcher = templateSources(s, mine, out);  // after the instances it calls
            out.push_back(std::move(dispatcher));
            continue;
        }
        for (const std::string& helper : mine.front()->function->includes)
            if (included.insert(helper).second) out.emplace_back(helper, file(helper));
        out.emplace_back(mine.front()->function->file, source(mine.front()->function));
    }
    return out;
}

std::pair<std::string, std::string> ProgramAssembly::templateSources(const SlotInfo& s,
                                                                     const std::vector<const Binding*>& mine,
                                                                     Sources& out) const
{
    // Each instance renamed apart into `out`; returns the slot function dispatching over them.
    std::string calls;
    for (const Binding* b : mine) {
        std::string text = renameIdentifier(source(b->function), s.function, s.function + b->suffix);
        for (const UniformDecl& u : b->function->uniforms)
            if (!u.shared) text = renameIdentifier(text, u.name, u.name + b->suffix);
        for (const TextureDecl& t : b->function->textures)
            if (!t.shared) text = renameIdentifier(text, t.name, t.name + b->suffix);
        out.emplace_back(b->function->file + " (instance " + std::to_string(b->instance) + ")", text);
        calls += (calls.empty() || s.join.empty() ? "" : s.join) + replaceAll(s.call, "{k}", std::to_string(b->instance));
    }
    const std::string body = mine.empty() ? s.empty : replaceAll(s.wrap, "{calls}", calls);
    return {"<" + s.name + " dispatcher over " + std::to_string(mine.size()) + " instances>",
            "// " + s.name + ": template over " + std::to_string(mine.size()) + " instances\n" + s.signature + "\n{\n" +
                body + "}\n"};
}

std::set<std::string> ProgramAssembly::memberSharedNames(const std::string& numerics) const
{
    // What a set defines once for all members: the numerics and the ray setup's helpers.
    std::set<std::string> shared = definedNames(numerics);
    for (const std::string& n : definedNames(file("RaySetup/ray.glsl"))) shared.insert(n);
    return shared;
}

void ProgramAssembly::appendMembers(const std::string& slotDeclarations)
{
    // Each member's slots, prototypes and glue, renamed apart by its suffix except for what the
    // set defines once; then, for every function the glue defines, a dispatcher over the members.
    const ShaderFunction* glue = lookup("MultiVolume", "member");
    const std::string glueSource = source(glue);
    for (std::size_t k = 0; k < _composition.members.size(); ++k) {
        const std::string suffix = "_v" + std::to_string(k);
        const std::string of = " (member " + std::to_string(k) + ")";
        append("slots.glsl" + of, renameForMember(slotDeclarations, _memberShared, suffix, _memberMacros));
        for (const auto& [name, text] : slotSources(int(k))) append(name + of, renameForMember(text, _memberShared, suffix, _memberMacros));
        append(glue->file + of, renameForMember(glueSource, _memberShared, suffix, _memberMacros));
    }
    append("<MultiVolume dispatchers over " + std::to_string(_composition.members.size()) + " members>",
           memberDispatchers(glueSource, _composition.members.size()));
}

void ProgramAssembly::assembleBuild(const std::string& declarations, const std::string& numerics,
                                    const std::string& slotDeclarations)
{
    // The compute program of each implementation that builds auxiliary data, a single volume's
    // (member -1) or a set member's: the same declarations (it reads the ray caster's uniforms
    // and textures) and the slots that sample and classify the volume, then the build file's
    // main(). A member's are renamed by its suffix, as in the ray caster, but for the uniforms
    // the build file declares itself (the C++ side sets them per dispatch by name).
    for (int member = -1; member < int(_composition.members.size()); ++member) {
        const ShaderFunction* builder = nullptr;
        for (const Binding& b : _result.bindings)
            if (b.member == member && !b.function->buildFile.empty()) builder = b.function;
        if (!builder) continue;
        std::string main;
        try {
            main = file(builder->buildFile);
        } catch (const std::exception& e) {
            throw std::runtime_error("slot " + builder->slot + ", implementation " + builder->name + ": " + e.what());
        }
        const std::string suffix = member < 0 ? "" : "_v" + std::to_string(member);
        const std::string of = member < 0 ? "" : " (member " + std::to_string(member) + ")";
        std::set<std::string> shared = _memberShared;  // a member's: and the build file's own uniforms
        static const std::regex ownUniform(R"(\buniform\s+\w+\s+(volren_\w+))");
        if (member >= 0)
            for (auto it = std::sregex_iterator(main.begin(), main.end(), ownUniform); it != std::sregex_iterator(); ++it)
                shared.insert((*it)[1].str());
        auto renamed = [&](const std::string& text) { return member < 0 ? text : renameForMember(text, shared, suffix, _memberMacros); };
        BuildProgram& build = _result.builds[member];
        std::ostringstream src;
        auto add = [&](const std::string& name, const std::string& text) {
            const int index = int(build.sourceNames.size());
            build.sourceNames.push_back(name + of);
            src << "// ---- " << name << of << " ----\n#line 1 " << index << "\n" << text << "\n";
        };
        src << header();
        build.sourceNames.push_back("<generated declarations>");
        src << declarations;
        add("common/numerics.glsl", numerics);
        add("slots.glsl", renamed(slotDeclarations));
        for (const auto& [name, text] : slotSources(member, &buildSamplingSlots())) add(name, renamed(text));
        add(builder->buildFile, renamed(main));
        build.source = src.str();
    }
}

const ShaderFunction* ProgramAssembly::assemble()
{
    pick(_composition, -1);
    for (std::size_t k = 0; k < _composition.members.size(); ++k) pick(_composition.members[k], int(k));
    _memberMacros = {"VOLREN_LIGHT_COUNT", "VOLREN_LIGHT_ARRAY"};
    for (const Binding& b : _result.bindings)
        for (const auto& define : b.function->defines) _memberMacros.insert(define.first);
    const std::string decls = declarations();
    _src << header();
    _result.sourceNames.push_back("<generated declarations>");
    _src << decls;
    const std::string numerics = file("common/numerics.glsl");
    const std::string slotDeclarations = file("slots.glsl");
    append("common/numerics.glsl", numerics);
    append("slots.glsl", slotDeclarations);
    for (const auto& [name, text] : slotSources(-1)) {
        if (_composition.members.empty()) {
            append(name, text);
            continue;
        }
        try {
            append(name, unrollMemberLoops(text, _composition.members.size()));
        } catch (const std::exception& e) {
            throw std::runtime_error(name + ": " + e.what());
        }
    }
    if (!_composition.members.empty()) {
        _memberShared = memberSharedNames(numerics);
        appendMembers(slotDeclarations);
    }
    _result.fragmentSource = _src.str();
    assembleBuild(decls, numerics, slotDeclarations);
    return _raySetup;
}

}  // namespace volren
