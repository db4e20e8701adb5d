#include <volume_renderer/ShaderCompositor.h>
#include <volume_renderer/Slots.h>

#include <osg/Notify>
#include <osg/Shader>

#include <cstdio>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace volren {

namespace {

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read shader file " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

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

const char* const glslVersion = "#version 430 core\n";

}  // namespace

bool ComposedProgram::needs(AuxData aux) const
{
    for (const Binding& b : bindings)
        for (AuxData a : b.function->needs)
            if (a == aux) return true;
    return false;
}

std::string Composition::functionFor(const std::string& slot) const
{
    if (auto it = choice.find(slot); it != choice.end()) return it->second;
    if (const SlotInfo* s = findSlot(slot)) return s->defaultFunction;
    return {};
}

std::string Composition::key() const
{
    std::string key;
    for (const SlotInfo& s : slots()) {
        key += s.name + "=";
        if (s.isTemplate) {
            key += "[";
            if (auto it = instances.find(s.name); it != instances.end())
                for (std::size_t i = 0; i < it->second.size(); ++i) key += (i ? "," : "") + it->second[i];
            key += "]";
        } else {
            key += functionFor(s.name);
        }
        key += ";";
    }
    key += "lights=" + std::to_string(lightCount) + ";";
    if (!members.empty()) {
        key += "members{";
        for (const Composition& m : members) key += m.key() + "|";
        key += "}";
    }
    return key;
}

ShaderCompositor::ShaderCompositor(const ShaderFunctionRegistry& registry) : _registry(registry) {}

std::size_t ShaderCompositor::programCount() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _cache.size();
}

std::shared_ptr<const ComposedProgram> ShaderCompositor::program(const Composition& composition)
{
    const std::string key = composition.key();
    {
        std::lock_guard<std::mutex> lock(_mutex);
        if (auto it = _cache.find(key); it != _cache.end()) return it->second;
    }
    std::shared_ptr<const ComposedProgram> built = build(composition);
    std::lock_guard<std::mutex> lock(_mutex);
    return _cache.emplace(key, built).first->second;
}

namespace {

void checkComposition(const Composition& composition)
{
    for (const auto& entry : composition.choice) {
        const SlotInfo* s = findSlot(entry.first);
        if (!s) throw std::runtime_error("composition names unknown slot '" + entry.first + "'");
        if (s->isTemplate) throw std::runtime_error("slot " + s->name + " takes instances, not a single choice");
    }
    for (const auto& entry : composition.instances) {
        const SlotInfo* s = findSlot(entry.first);
        if (!s || !s->isTemplate) throw std::runtime_error("'" + entry.first + "' is not a template slot");
    }
    if (composition.lightCount > 64) throw std::runtime_error("at most 64 lights per volume");
}

/// Slots a multi-volume member brings into its set's program (the set owns the others).
bool isMemberSlot(const std::string& slot)
{
    return slot != "RaySetup" && slot != "RayTraversal" && slot != "Jitter" && slot != "Acceleration";
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
/// per-composition macros (VOLREN_LIGHT_COUNT, VOLREN_LIGHT_ARRAY) too.
std::string renameForMember(const std::string& text, const std::set<std::string>& shared, const std::string& suffix)
{
    static const std::regex name(R"(\b(volren_\w+|VOLREN_LIGHT_COUNT|VOLREN_LIGHT_ARRAY)\b)");
    std::string out;
    auto last = text.cbegin();
    for (auto it = std::sregex_iterator(text.begin(), text.end(), name); it != std::sregex_iterator(); ++it) {
        out.append(last, text.cbegin() + it->position());
        out += it->str();
        if (!shared.count(it->str())) out += suffix;
        last = text.cbegin() + it->position() + it->length();
    }
    out.append(last, text.cend());
    return out;
}

}  // namespace

std::shared_ptr<const ComposedProgram> ShaderCompositor::build(const Composition& composition) const
{
    checkComposition(composition);
    for (const Composition& m : composition.members) {
        checkComposition(m);
        if (!m.members.empty()) throw std::runtime_error("a multi-volume member cannot be a set itself");
    }

    auto result = std::make_shared<ComposedProgram>();
    result->key = composition.key();
    auto lookup = [&](const std::string& slot, const std::string& name) {
        const ShaderFunction* f = _registry.find(slot, name);
        if (!f) {
            std::string known;
            for (const auto& n : _registry.names(slot)) known += (known.empty() ? "" : ", ") + n;
            throw std::runtime_error("slot " + slot + ": no implementation '" + name + "' (known: " + known + ")");
        }
        return f;
    };

    // Pick the implementations: one per ordinary slot, one per instance of template slots; for
    // a multi-volume set, the set's own and then every member's (with the member's suffix).
    const ShaderFunction* raySetup = nullptr;
    auto pick = [&](const Composition& c, int member) {
        const std::string memberSuffix = member < 0 ? "" : "_v" + std::to_string(member);
        for (const SlotInfo& s : slots()) {
            if (s.isTemplate) {
                auto it = c.instances.find(s.name);
                const std::vector<std::string> none;
                const std::vector<std::string>& names = it == c.instances.end() ? none : it->second;
                for (std::size_t k = 0; k < names.size(); ++k)
                    result->bindings.push_back(
                        {lookup(s.name, names[k]), "_" + std::to_string(k), int(k), member, memberSuffix});
                continue;
            }
            const ShaderFunction* f = lookup(s.name, c.functionFor(s.name));
            if (f->multiVolume != (member < 0 && !composition.members.empty()) && s.name == "RayTraversal")
                throw std::runtime_error("slot RayTraversal: '" + f->name + "' " +
                                         (f->multiVolume ? "only marches a multi-volume set" : "cannot march a multi-volume set"));
            result->bindings.push_back({f, "", -1, member, memberSuffix});
            if (member >= 0) continue;
            if (s.name == "RaySetup") raySetup = f;
            if (s.name == "RayTraversal") result->writesDepth = f->writesDepth;
        }
        if (member >= 0) result->bindings.push_back({lookup("MultiVolume", "member"), "", -1, member, memberSuffix});
    };
    pick(composition, -1);
    for (std::size_t k = 0; k < composition.members.size(); ++k) pick(composition.members[k], int(k));

    // Declarations: each uniform and sampler once; a clash in type is an error naming both.
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
    for (const Binding& b : result->bindings) {
        for (const TextureDecl& t : b.function->textures) {
            const std::string name = (t.shared ? t.name : t.name + b.suffix) + b.memberSuffix;
            if (!result->textureUnits.count(name)) result->textureUnits[name] = nextUnit++;
            declare(name, t.samplerType, b.function);
        }
        for (const UniformDecl& u : b.function->uniforms) {
            const std::string name = (u.shared ? u.name : u.name + b.suffix) + b.memberSuffix;
            const std::string size = u.arraySize.rfind("VOLREN_", 0) == 0 ? u.arraySize + b.memberSuffix : u.arraySize;
            declare(size.empty() ? name : name + "[" + size + "]", u.glslType, b.function);
        }
    }

    // Source strings: 0 = generated header; then common files; then one per implementation.
    std::ostringstream src;
    src << glslVersion;
    src << "// volren composed ray caster: " << result->key << "\n";
    src << "#define VOLREN_LIGHT_COUNT " << composition.lightCount << "\n";
    src << "#define VOLREN_LIGHT_ARRAY " << std::max(1u, composition.lightCount) << "\n";
    if (!composition.members.empty()) src << "#define VOLREN_MEMBER_COUNT " << composition.members.size() << "\n";
    for (std::size_t k = 0; k < composition.members.size(); ++k) {
        const unsigned int lights = composition.members[k].lightCount;
        src << "#define VOLREN_LIGHT_COUNT_v" << k << " " << lights << "\n";
        src << "#define VOLREN_LIGHT_ARRAY_v" << k << " " << std::max(1u, lights) << "\n";
    }
    result->sourceNames.push_back("<generated declarations>");
    src << decls.str();
    auto append = [&](const std::string& name, const std::string& text) {
        const int index = int(result->sourceNames.size());
        result->sourceNames.push_back(name);
        src << "// ---- " << name << " ----\n#line 1 " << index << "\n" << text << "\n";
    };
    auto source = [&](const ShaderFunction* f) {
        try {
            return readText(_registry.locate(f->file));
        } catch (const std::exception& e) {
            throw std::runtime_error("slot " + f->slot + ", implementation " + f->name + ": " + e.what());
        }
    };
    // The slots of the set's own composition (member < 0), or of one member: the source files in
    // emission order, as (name, text).
    auto slotSources = [&](int member) {
        std::vector<std::pair<std::string, std::string>> out;
        std::set<std::string> included;
        auto includes = [&](const ShaderFunction* f) {
            for (const std::string& file : f->includes)
                if (included.insert(file).second) out.emplace_back(file, readText(_registry.locate(file)));
        };
        for (const SlotInfo& s : slots()) {
            if (member >= 0 && !isMemberSlot(s.name)) continue;
            std::vector<const Binding*> mine;
            for (const Binding& b : result->bindings)
                if (b.member == member && b.function->slot == s.name) mine.push_back(&b);
            if (!s.isTemplate) {
                includes(mine.front()->function);
                out.emplace_back(mine.front()->function->file, source(mine.front()->function));
                continue;
            }
            // Template: each instance renamed apart, then the slot function dispatches over them.
            std::string calls;
            for (const Binding* b : mine) {
                std::string text = renameIdentifier(source(b->function), s.function, s.function + b->suffix);
                for (const UniformDecl& u : b->function->uniforms)
                    if (!u.shared) text = renameIdentifier(text, u.name, u.name + b->suffix);
                for (const TextureDecl& t : b->function->textures)
                    if (!t.shared) text = renameIdentifier(text, t.name, t.name + b->suffix);
                out.emplace_back(b->function->file + " (instance " + std::to_string(b->instance) + ")", text);
                calls += (calls.empty() || s.join.empty() ? "" : s.join) +
                         replaceAll(s.call, "{k}", std::to_string(b->instance));
            }
            const std::string body = mine.empty() ? s.empty : replaceAll(s.wrap, "{calls}", calls);
            out.emplace_back("<" + s.name + " dispatcher over " + std::to_string(mine.size()) + " instances>",
                             "// " + s.name + ": template over " + std::to_string(mine.size()) + " instances\n" +
                                 s.signature + "\n{\n" + body + "}\n");
        }
        return out;
    };
    const std::string numerics = readText(_registry.locate("common/numerics.glsl"));
    const std::string slotDeclarations = readText(_registry.locate("slots.glsl"));
    append("common/numerics.glsl", numerics);
    append("slots.glsl", slotDeclarations);
    for (const auto& [name, text] : slotSources(-1)) append(name, text);

    // Multi-volume members: each member's slots, prototypes and glue, renamed apart by its
    // suffix except for what the set defines once; then dispatchers over the members.
    if (!composition.members.empty()) {
        std::set<std::string> shared = definedNames(numerics);
        for (const std::string& n : definedNames(readText(_registry.locate("RaySetup/ray.glsl")))) shared.insert(n);
        const ShaderFunction* glue = lookup("MultiVolume", "member");
        std::string rays, samples;
        for (std::size_t k = 0; k < composition.members.size(); ++k) {
            const std::string suffix = "_v" + std::to_string(k);
            const std::string of = " (member " + std::to_string(k) + ")";
            append("slots.glsl" + of, renameForMember(slotDeclarations, shared, suffix));
            for (const auto& [name, text] : slotSources(int(k))) append(name + of, renameForMember(text, shared, suffix));
            append(glue->file + of, renameForMember(source(glue), shared, suffix));
            const std::string branch = std::string(k ? "    else if" : "    if") + " (k == " + std::to_string(k) + ")";
            rays += branch + " volren_memberRay" + suffix +
                    "(origin, dir, memberOrigin, memberDir, worldPerT, tNear, tFar);\n";
            samples += branch + " return volren_memberSample" + suffix + "(pos, memberDir, worldLength, emitted);\n";
        }
        append("<MultiVolume dispatchers over " + std::to_string(composition.members.size()) + " members>",
               "void volren_setMemberRay(int k, vec3 origin, vec3 dir, out vec3 memberOrigin, out vec3 memberDir,\n"
               "                         out float worldPerT, inout float tNear, inout float tFar)\n{\n"
               "    memberOrigin = vec3(0.0);\n    memberDir = vec3(0.0);\n    worldPerT = 0.0;\n" +
                   rays +
                   "}\n"
                   "float volren_setMemberSample(int k, vec3 pos, vec3 memberDir, float worldLength, out vec3 emitted)\n{\n" +
                   samples + "    emitted = vec3(0.0);\n    return 0.0;\n}\n");
    }
    result->fragmentSource = src.str();

    // GL object labels are limited to 256 characters (OSG labels programs by name), so the
    // name is a short digest; the full key stays in ComposedProgram::key.
    char label[64];
    std::snprintf(label, sizeof(label), "volren ray caster %016zx", std::hash<std::string>()(result->key));
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName(label);
    const std::string vertexFile = raySetup->vertexFile;
    osg::ref_ptr<osg::Shader> vertex = new osg::Shader(osg::Shader::VERTEX, readText(_registry.locate(vertexFile)));
    vertex->setName(vertexFile);
    osg::ref_ptr<osg::Shader> fragment = new osg::Shader(osg::Shader::FRAGMENT, result->fragmentSource);
    fragment->setName(std::string(label) + " fragment");
    program->addShader(vertex);
    program->addShader(fragment);
    program->addBindFragDataLocation("volren_fragColor", 0);
    result->program = program;
    OSG_INFO << "volren: composed program " << result->key << std::endl;
    return result;
}

std::string ShaderCompositor::explainLog(const std::string& log, const ComposedProgram& program)
{
    // Mesa writes "N:LINE(COL): error", NVIDIA "N(LINE) : error"; N is the #line source-string number.
    static const std::regex ref(R"(^(\d+)(?::(\d+)\(\d+\)|\((\d+)\)))");
    std::istringstream lines(log);
    std::string line, out;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_search(line, m, ref)) {
            const std::size_t index = std::stoul(m[1].str());
            const std::string lineNo = m[2].matched ? m[2].str() : m[3].str();
            if (index < program.sourceNames.size())
                line = program.sourceNames[index] + ":" + lineNo + line.substr(std::size_t(m.length()));
        }
        out += line + "\n";
    }
    return out;
}

}  // namespace volren
