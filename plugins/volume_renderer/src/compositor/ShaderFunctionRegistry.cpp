#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/Slots.h>

#include <volume_model/DeclarationLoader.h>
#include <volume_model/ParameterCatalog.h>
#include <volume_model/ReferenceModel.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <osg/Notify>

#include <cstdlib>
#include <fstream>
#include <dlfcn.h>
#include <set>
#include <sstream>
#include <stdexcept>

namespace volren {

namespace {

/// The model's catalogs of parameters and reference models are filled by the registry: a
/// look-up there loads it.
[[maybe_unused]] const bool declarationLoader = (setDeclarationLoader([] { ShaderFunctionRegistry::instance(); }), true);

}  // namespace

ShaderFunctionRegistry& ShaderFunctionRegistry::instance()
{
    static ShaderFunctionRegistry* registry = [] {
        auto* r = new ShaderFunctionRegistry;
        r->addBuiltins();
        for (const std::string& failure : r->loadPlugins()) OSG_WARN << "volren: " << failure << std::endl;
        r->addShaderDirectoryFunctions();
        for (const std::string& missing : r->undeclaredNeeds()) OSG_WARN << "volren: " << missing << std::endl;
        return r;
    }();
    return *registry;
}

void ShaderFunctionRegistry::addBuiltins()
{
    registerRaySetupFunctions(*this);
    registerClipRayFunctions(*this);
    registerJitterFunctions(*this);
    registerRayTraversalFunctions(*this);
    registerClipPositionFunctions(*this);
    registerReconstructionFunctions(*this);
    registerVolumeStorageFunctions(*this);
    registerClassificationFunctions(*this);
    registerShadingFunctions(*this);
    registerGradientFunctions(*this);
    registerGradientInputFunctions(*this);
    registerIlluminationFunctions(*this);
    registerShadowingFunctions(*this);
    registerAccelerationFunctions(*this);
    registerWeightingFunctions(*this);
    registerMultiVolumeFunctions(*this);
}

namespace {

std::vector<std::string> pathList(const char* variable)
{
    std::vector<std::string> dirs;
    if (const char* env = std::getenv(variable); env && *env) {
        std::stringstream list(env);
        std::string dir;
        while (std::getline(list, dir, ':'))
            if (!dir.empty()) dirs.push_back(dir);
    }
    return dirs;
}

}  // namespace

std::vector<std::string> ShaderFunctionRegistry::loadPlugins()
{
    using RegisterFunction = void (*)(ShaderFunctionRegistry&);
    std::vector<std::string> failures;
    for (const std::string& dir : pathList("VOLREN_FUNCTION_PATH")) {
        for (const std::string& file : osgDB::getDirectoryContents(dir)) {
            if (file.rfind("volren_functions_", 0) != 0 || osgDB::getFileExtension(file) != "so") continue;
            const std::string path = osgDB::concatPaths(dir, file);
            void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!handle) {
                failures.push_back(path + ": " + dlerror());
                continue;
            }
            auto registerFunctions = reinterpret_cast<RegisterFunction>(dlsym(handle, "volrenRegisterShaderFunctions"));
            if (!registerFunctions) {
                failures.push_back(path + ": no volrenRegisterShaderFunctions symbol");
                continue;
            }
            try {
                registerFunctions(*this);  // the library stays loaded: its bind functions are used
            } catch (const std::exception& e) {
                failures.push_back(path + ": " + e.what());
            }
        }
    }
    return failures;
}

std::size_t ShaderFunctionRegistry::addShaderDirectoryFunctions()
{
    // The files registered implementations read (their own, includes, builds): a copy of one on
    // the path overrides it and is not an implementation of its own.
    std::set<std::string> used;
    for (const auto& [slot, functions] : _functions)
        for (const auto& [name, f] : functions) {
            used.insert(f.file);
            used.insert(f.includes.begin(), f.includes.end());
        }
    std::size_t added = 0;
    for (const std::string& dir : pathList("VOLREN_SHADER_PATH")) {
        for (const SlotInfo& slot : slots()) {
            for (const std::string& file : osgDB::getDirectoryContents(osgDB::concatPaths(dir, slot.name))) {
                if (osgDB::getFileExtension(file) != "glsl") continue;
                const std::string name = osgDB::getNameLessExtension(file);
                if (find(slot.name, name) || used.count(slot.name + "/" + file)) continue;  // an override of a registered one
                const ShaderFunction* base = find(slot.name, "null");
                ShaderFunction f;
                f.slot = slot.name;
                f.name = name;
                f.file = slot.name + "/" + file;
                if (base) f.vertexFile = base->vertexFile;
                add(f);
                ++added;
            }
        }
    }
    return added;
}

void ShaderFunctionRegistry::add(ShaderFunction function)
{
    if (function.file.empty()) function.file = function.slot + "/" + function.name + ".glsl";
    for (ParameterDecl& p : function.parameters) {
        p.slot = function.slot;
        p.implementations = {function.name};
        ParameterCatalog::instance().declare(p);
    }
    if (function.reference) ReferenceModelCatalog::instance().declare(function.slot, function.name, *function.reference);
    const std::string slot = function.slot, name = function.name;
    _functions[slot][name] = std::move(function);
}

void ShaderFunctionRegistry::addSlotParameter(const std::string& slot, ParameterDecl parameter)
{
    parameter.slot = slot;
    parameter.implementations.clear();
    ParameterCatalog::instance().declare(parameter);
}

void ShaderFunctionRegistry::addAuxKind(AuxKind kind)
{
    if (_auxKinds.count(kind.name)) throw std::logic_error("auxiliary data kind '" + kind.name + "' is declared twice");
    const bool made = kind.scope == AuxScope::Volume ? bool(kind.provide) != kind.build.has_value()
                                                     : kind.scope != AuxScope::Camera || bool(kind.perCamera);
    if (!made)
        throw std::logic_error("auxiliary data kind '" + kind.name +
                               "' must say how it is made (a Volume kind: provide or build, one of them; a Camera kind: perCamera)");
    if (kind.build && (!kind.build->dims || !kind.build->channels || !kind.build->plan || kind.build->sampler.empty()))
        throw std::logic_error("auxiliary data kind '" + kind.name + "': its build needs a sampler, dims, channels and a plan");
    const std::string name = kind.name;
    _auxKinds.emplace(name, std::move(kind));
}

const AuxKind* ShaderFunctionRegistry::auxKind(const std::string& name) const
{
    auto it = _auxKinds.find(name);
    return it == _auxKinds.end() ? nullptr : &it->second;
}

std::vector<const AuxKind*> ShaderFunctionRegistry::auxKindsOf(const ShaderFunction& function) const
{
    std::vector<const AuxKind*> kinds;
    for (const std::string& name : function.needs) {
        const AuxKind* kind = auxKind(name);
        if (!kind)
            throw std::runtime_error(function.slot + " " + function.name + " needs auxiliary data '" + name +
                                     "', a kind no one declared (ShaderFunctionRegistry::addAuxKind)");
        kinds.push_back(kind);
    }
    return kinds;
}

bool ShaderFunctionRegistry::darkensGeometry(const ShaderFunction& function) const
{
    for (const std::string& name : function.needs)
        if (const AuxKind* kind = auxKind(name); kind && kind->darkensGeometry) return true;
    return false;
}

std::vector<std::string> ShaderFunctionRegistry::undeclaredNeeds() const
{
    std::vector<std::string> out;
    for (const auto& [slot, functions] : _functions)
        for (const auto& [name, f] : functions)
            for (const std::string& kind : f.needs)
                if (!auxKind(kind))
                    out.push_back(slot + " " + name + " needs auxiliary data '" + kind + "', a kind no one declared");
    return out;
}

const ShaderFunction* ShaderFunctionRegistry::find(const std::string& slot, const std::string& name) const
{
    auto s = _functions.find(slot);
    if (s == _functions.end()) return nullptr;
    auto f = s->second.find(name);
    return f == s->second.end() ? nullptr : &f->second;
}

std::vector<std::string> ShaderFunctionRegistry::names(const std::string& slot) const
{
    std::vector<std::string> out;
    if (auto s = _functions.find(slot); s != _functions.end())
        for (const auto& entry : s->second)
            if (!entry.second.traits.multiVolume) out.push_back(entry.first);
    return out;
}

std::vector<std::string> ShaderFunctionRegistry::allNames(const std::string& slot) const
{
    std::vector<std::string> out;
    if (auto s = _functions.find(slot); s != _functions.end())
        for (const auto& entry : s->second) out.push_back(entry.first);
    return out;
}

std::vector<std::string> ShaderFunctionRegistry::shaderDirectories() const
{
    std::vector<std::string> dirs = pathList("VOLREN_SHADER_PATH");
    dirs.push_back(osgDB::concatPaths(shareDirectory(), "shaders"));
    return dirs;
}

std::string ShaderFunctionRegistry::locate(const std::string& relative) const
{
    std::string searched;
    for (const std::string& dir : shaderDirectories()) {
        const std::string path = osgDB::concatPaths(dir, relative);
        if (osgDB::fileExists(path)) return path;
        searched += (searched.empty() ? "" : ", ") + dir;
    }
    throw std::runtime_error("shader file '" + relative + "' not found (searched: " + searched +
                             "; set VOLREN_SHADER_PATH or VOLREN_SHARE_DIR)");
}

std::string ShaderFunctionRegistry::read(const std::string& relative) const
{
    const std::string path = locate(relative);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read shader file " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace volren
