#include "ProgramAssembly.h"

#include <volume_renderer/ShaderCompositor.h>
#include <volume_renderer/Slots.h>

#include <osg/Notify>
#include <osg/Shader>

#include <cstdio>
#include <functional>
#include <regex>
#include <stdexcept>

namespace volren {

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

}  // namespace

const BuildProgram* ComposedProgram::build(int member) const
{
    auto it = builds.find(member);
    return it == builds.end() ? nullptr : &it->second;
}

ShaderCompositor::ShaderCompositor(const ShaderFunctionRegistry& registry) : _registry(registry) {}

std::size_t ShaderCompositor::programCount() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    std::size_t alive = 0;
    for (const auto& entry : _live) alive += !entry.second.expired();
    return alive;
}

void ShaderCompositor::setCacheSize(std::size_t programs)
{
    std::lock_guard<std::mutex> lock(_mutex);
    _cacheSize = programs;
    while (_recent.size() > _cacheSize) _recent.pop_back();
}

void ShaderCompositor::touch(const std::shared_ptr<const ComposedProgram>& program)
{
    // Caller holds the lock. Most recent first; the oldest unused ones are let go.
    _recent.remove(program);
    _recent.push_front(program);
    while (_recent.size() > _cacheSize) _recent.pop_back();
    for (auto it = _live.begin(); it != _live.end();) it = it->second.expired() ? _live.erase(it) : std::next(it);
}

std::shared_ptr<const ComposedProgram> ShaderCompositor::program(const Composition& composition)
{
    const std::string key = composition.key();
    {
        std::lock_guard<std::mutex> lock(_mutex);
        if (auto it = _live.find(key); it != _live.end())
            if (std::shared_ptr<const ComposedProgram> alive = it->second.lock()) {
                touch(alive);
                return alive;
            }
    }
    std::shared_ptr<const ComposedProgram> built = build(composition);
    std::lock_guard<std::mutex> lock(_mutex);
    if (auto it = _live.find(key); it != _live.end())  // built meanwhile by another thread
        if (std::shared_ptr<const ComposedProgram> alive = it->second.lock()) built = alive;
    _live[key] = built;
    touch(built);
    return built;
}

std::shared_ptr<const ComposedProgram> ShaderCompositor::build(const Composition& composition) const
{
    checkComposition(composition);
    for (const Composition& m : composition.members) {
        checkComposition(m);
        if (!m.members.empty()) throw std::runtime_error("a multi-volume member cannot be a set itself");
    }
    auto result = std::make_shared<ComposedProgram>();
    result->key = composition.key();
    const ShaderFunction* raySetup = ProgramAssembly(_registry, composition, *result).assemble();

    // GL object labels are limited to 256 characters (OSG labels programs by name), so the
    // name is a short digest; the full key stays in ComposedProgram::key.
    char label[64];
    std::snprintf(label, sizeof(label), "volren ray caster %016zx", std::hash<std::string>()(result->key));
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName(label);
    osg::ref_ptr<osg::Shader> vertex =
        new osg::Shader(osg::Shader::VERTEX, _registry.read(raySetup->vertexFile));
    vertex->setName(raySetup->vertexFile);
    osg::ref_ptr<osg::Shader> fragment = new osg::Shader(osg::Shader::FRAGMENT, result->fragmentSource);
    fragment->setName(std::string(label) + " fragment");
    program->addShader(vertex);
    program->addShader(fragment);
    program->addBindFragDataLocation("volren_fragColor", 0);
    result->program = program;
    for (auto& [member, build] : result->builds) {
        const std::string name = std::string(label) + " build" + (member < 0 ? "" : " of member " + std::to_string(member));
        build.program = new osg::Program;
        build.program->setName(name);
        osg::ref_ptr<osg::Shader> compute = new osg::Shader(osg::Shader::COMPUTE, build.source);
        compute->setName(name + " compute");
        build.program->addShader(compute);
    }
    OSG_INFO << "volren: composed program " << result->key << std::endl;
    return result;
}

std::string ShaderCompositor::explainLog(const std::string& log, const ComposedProgram& program)
{
    return explainLog(log, program.sourceNames);
}

std::string ShaderCompositor::explainLog(const std::string& log, const std::vector<std::string>& sourceNames)
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
            if (index < sourceNames.size())
                line = sourceNames[index] + ":" + lineNo + line.substr(std::size_t(m.length()));
        }
        out += line + "\n";
    }
    return out;
}

}  // namespace volren
