#include <volume_renderer/ShaderCompositor.h>
#include <volume_renderer/Slots.h>

#include <osg/Notify>
#include <osg/Shader>

#include <fstream>
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

const char* const glslVersion = "#version 430 core\n";

}  // namespace

std::string Composition::functionFor(const std::string& slot) const
{
    if (auto it = choice.find(slot); it != choice.end()) return it->second;
    for (const SlotInfo& s : slots())
        if (s.name == slot) return s.defaultFunction;
    return {};
}

std::string Composition::key() const
{
    std::string key;
    for (const SlotInfo& s : slots()) key += s.name + "=" + functionFor(s.name) + ";";
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

std::shared_ptr<const ComposedProgram> ShaderCompositor::build(const Composition& composition) const
{
    for (const auto& [slot, name] : composition.choice) {
        bool known = false;
        for (const SlotInfo& s : slots()) known = known || s.name == slot;
        if (!known) throw std::runtime_error("composition names unknown slot '" + slot + "'");
    }

    auto result = std::make_shared<ComposedProgram>();
    result->key = composition.key();

    // Pick one implementation per slot.
    const ShaderFunction* raySetup = nullptr;
    for (const SlotInfo& s : slots()) {
        const std::string name = composition.functionFor(s.name);
        const ShaderFunction* f = _registry.find(s.name, name);
        if (!f) {
            std::string known;
            for (const auto& n : _registry.names(s.name)) known += (known.empty() ? "" : ", ") + n;
            throw std::runtime_error("slot " + s.name + ": no implementation '" + name + "' (known: " + known + ")");
        }
        result->functions.push_back(f);
        if (s.name == "RaySetup") raySetup = f;
    }

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
    for (const ShaderFunction* f : result->functions) {
        for (const TextureDecl& t : f->textures) {
            if (!result->textureUnits.count(t.name)) result->textureUnits[t.name] = nextUnit++;
            declare(t.name, t.samplerType, f);
        }
        for (const UniformDecl& u : f->uniforms) declare(u.name, u.glslType, f);
    }

    // Source strings: 0 = generated header; then common files; then one per implementation.
    std::ostringstream src;
    src << glslVersion;
    src << "// volren composed ray caster: " << result->key << "\n";
    result->sourceNames.push_back("<generated declarations>");
    src << decls.str();
    auto append = [&](const std::string& relative) {
        const int index = int(result->sourceNames.size());
        result->sourceNames.push_back(relative);
        src << "#line 1 " << index << "\n" << readText(_registry.locate(relative)) << "\n";
    };
    append("common/numerics.glsl");
    append("slots.glsl");
    for (const ShaderFunction* f : result->functions) {
        try {
            append(f->file);
        } catch (const std::exception& e) {
            throw std::runtime_error("slot " + f->slot + ", implementation " + f->name + ": " + e.what());
        }
    }
    result->fragmentSource = src.str();

    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName(result->key);
    const std::string vertexFile = raySetup->vertexFile;
    osg::ref_ptr<osg::Shader> vertex = new osg::Shader(osg::Shader::VERTEX, readText(_registry.locate(vertexFile)));
    vertex->setName(vertexFile);
    osg::ref_ptr<osg::Shader> fragment = new osg::Shader(osg::Shader::FRAGMENT, result->fragmentSource);
    fragment->setName("composed:" + result->key);
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
