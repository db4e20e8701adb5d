#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace volren {

ShaderFunctionRegistry& ShaderFunctionRegistry::instance()
{
    static ShaderFunctionRegistry* registry = [] {
        auto* r = new ShaderFunctionRegistry;
        registerRaySetupFunctions(*r);
        registerClipRayFunctions(*r);
        registerJitterFunctions(*r);
        registerRayTraversalFunctions(*r);
        registerClipPositionFunctions(*r);
        registerReconstructionFunctions(*r);
        registerClassificationFunctions(*r);
        registerShadingFunctions(*r);
        return r;
    }();
    return *registry;
}

void ShaderFunctionRegistry::add(ShaderFunction function)
{
    const std::string slot = function.slot, name = function.name;
    _functions[slot][name] = std::move(function);
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
        for (const auto& entry : s->second) out.push_back(entry.first);
    return out;
}

std::vector<std::string> ShaderFunctionRegistry::shaderDirectories() const
{
    std::vector<std::string> dirs;
    if (const char* env = std::getenv("VOLREN_SHADER_PATH"); env && *env) {
        std::stringstream list(env);
        std::string dir;
        while (std::getline(list, dir, ':'))
            if (!dir.empty()) dirs.push_back(dir);
    }
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

void BindContext::texture(const std::string& name, osg::Texture* tex)
{
    auto unit = textureUnits.find(name);
    if (unit == textureUnits.end()) return;  // not used by this composition
    // Attribute only: shaders sample it; fixed-function texture modes are invalid in core profiles.
    stateSet.setTextureAttribute(unit->second, tex, osg::StateAttribute::ON);
    uniform(name, unit->second);
}

}  // namespace volren
