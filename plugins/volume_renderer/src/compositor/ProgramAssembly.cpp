#include "ProgramAssembly.h"
#include "BuildSlots.h"

#include <volume_renderer/Slots.h>

#include <algorithm>
#include <map>
#include <regex>
#include <stdexcept>

namespace volren {

namespace {

std::string replaceAll(std::string text, const std::string& from, const std::string& to)
{
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

/// Renames whole-word identifier `from` to `to` in GLSL source.
std::string renameIdentifier(const std::string& text, const std::string& from, const std::string& to)
{
    return std::regex_replace(text, std::regex("\\b" + from + "\\b"), to);
}

/// Names a file defines at its top level (functions and global variables).
std::set<std::string> definedNames(const std::string& text)
{
    static const std::regex definition(R"((?:^|\n)(?:float|int|bool|void|vec[234]|mat[234])\s+(volren_\w+))");
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), definition); it != std::sregex_iterator(); ++it)
        names.insert((*it)[1].str());
    return names;
}

/// Gives every volren_ name in `text` that is not in `shared` the member suffix, and the
/// per-composition macros (`macros`: the light count and the implementations' defines) too.
std::string renameForMember(const std::string& text, const std::set<std::string>& shared, const std::string& suffix,
                            const std::set<std::string>& macros)
{
    static const std::regex name(R"(\b(volren_\w+|VOLREN_\w+)\b)");
    std::string out;
    auto last = text.cbegin();
    for (auto it = std::sregex_iterator(text.begin(), text.end(), name); it != std::sregex_iterator(); ++it) {
        out.append(last, text.cbegin() + it->position());
        out += it->str();
        const bool macro = it->str().rfind("VOLREN_", 0) == 0;
        if (macro ? macros.count(it->str()) > 0 : !shared.count(it->str())) out += suffix;
        last = text.cbegin() + it->position() + it->length();
    }
    out.append(last, text.cend());
    return out;
}

const char* const glslVersion = "#version 430 core\n";

/// The set traversal's loops over members, `for (int k = 0; k < VOLREN_MEMBER_COUNT[ && C]; ++k)
/// { body }`, written out once per member: `do { const int k = <n>; [if (!(C)) break;] body }
/// while (false);` (a `continue` in the body ends that member's pass, as in the loop). A member's
/// dispatchers then see a constant k and call it alone: GPUs that run both sides of a branch
/// under a mask (llvmpipe) would otherwise pay every member's code for each call. C must stay
/// false once it is false (it is checked before each member); a `break` in the body is refused.
std::string unrollMemberLoops(const std::string& text, std::size_t members)
{
    static const std::regex header(
        R"(for\s*\(\s*int\s+k\s*=\s*0\s*;\s*k\s*<\s*VOLREN_MEMBER_COUNT\s*(?:&&\s*([^;]+?))?\s*;\s*\+\+k\s*\)\s*\{)");
    static const std::regex breaks(R"(\bbreak\b)");
    std::string out;
    std::size_t from = 0;
    for (std::smatch m; std::regex_search(text.cbegin() + std::ptrdiff_t(from), text.cend(), m, header);) {
        const std::size_t start = from + std::size_t(m.position());
        const std::size_t open = start + std::size_t(m.length()) - 1;
        std::size_t close = open;
        for (int depth = 0; close < text.size(); ++close) {
            depth += text[close] == '{' ? 1 : text[close] == '}' ? -1 : 0;
            if (depth == 0) break;
        }
        if (close >= text.size()) throw std::runtime_error("a loop over the members has no closing brace");
        const std::string body = text.substr(open + 1, close - open - 1);
        if (std::regex_search(body, breaks))
            throw std::runtime_error("a loop over the members has a break (written out per member, it would end one "
                                     "member's pass only)");
        const std::string condition = m[1].matched ? m[1].str() : std::string();
        out.append(text, from, start - from);
        for (std::size_t k = 0; k < members; ++k)
            out += "do { const int k = " + std::to_string(k) + ";" +
                   (condition.empty() ? std::string() : " if (!(" + condition + ")) break;") + body + "} while (false);";
        // What follows keeps its line numbers (compile errors name the file's own lines).
        out += "\n#line " + std::to_string(1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(close), '\n')) + "\n";
        from = close + 1;
    }
    out.append(text, from, std::string::npos);
    return out;
}

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
                _result.bindings.push_back({lookup(s.name, names[k]), "_" + std::to_string(k), int(k), member, memberSuffix});
            continue;
        }
        const ShaderFunction* f = lookup(s.name, c.functionFor(s.name));
        if (f->traits.multiVolume != (member < 0 && !_composition.members.empty()) && s.name == "RayTraversal")
            throw std::runtime_error("slot RayTraversal: '" + f->name + "' " +
                                     (f->traits.multiVolume ? "only marches a multi-volume set"
                                                            : "cannot march a multi-volume set"));
        _result.bindings.push_back({f, "", -1, member, memberSuffix});
        if (member >= 0) continue;
        if (s.name == "RaySetup") _raySetup = f;
        if (s.name == "RayTraversal") _result.writesDepth = f->traits.writesDepth;
    }
    if (member >= 0) _result.bindings.push_back({lookup("MultiVolume", "member"), "", -1, member, memberSuffix});
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
           memberDispatchers(glueSource));
}

std::string ProgramAssembly::memberDispatchers(const std::string& glue) const
{
    // `T volren_memberX(params)` defined by the glue -> `T volren_setMemberX(int k, params)`
    // calling member k's copy; an index out of range returns T's zero.
    static const std::regex definition(
        R"((?:^|\n)(void|float|bool|int|vec[234])\s+volren_member(\w+)\s*\(([^)]*)\)\s*\{)");
    static const std::regex parameterName(R"((\w+)\s*$)");
    std::string out;
    for (auto it = std::sregex_iterator(glue.begin(), glue.end(), definition); it != std::sregex_iterator(); ++it) {
        const std::string type = (*it)[1], name = (*it)[2], parameters = (*it)[3];
        std::string arguments;
        std::stringstream list(parameters);
        for (std::string parameter; std::getline(list, parameter, ',');) {
            std::smatch m;
            if (!std::regex_search(parameter, m, parameterName))
                throw std::runtime_error("MultiVolume/member: cannot read parameter '" + parameter + "' of volren_member" + name);
            arguments += (arguments.empty() ? "" : ", ") + m[1].str();
        }
        out += type + " volren_setMember" + name + "(int k" + (parameters.find_first_not_of(" \n") == std::string::npos ? "" : ", " + parameters) +
               ")\n{\n";
        for (std::size_t k = 0; k < _composition.members.size(); ++k)
            out += std::string(k ? "    else if" : "    if") + " (k == " + std::to_string(k) + ") " +
                   (type == "void" ? "" : "return ") + "volren_member" + name + "_v" + std::to_string(k) + "(" +
                   arguments + ");\n";
        if (type == "bool") out += "    return false;\n";
        else if (type != "void") out += "    return " + type + "(0);\n";
        out += "}\n";
    }
    return out;
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
