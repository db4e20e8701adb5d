#pragma once
#include <volume_renderer/ShaderFunction.h>

#include <map>
#include <string>
#include <vector>

namespace volren {

/// Every known shader-function implementation, by slot and name.
class ShaderFunctionRegistry
{
public:
    /// The process-wide registry, filled with volren's built-in implementations.
    static ShaderFunctionRegistry& instance();

    /// Adds or replaces an implementation (plugins may add their own).
    void add(ShaderFunction function);
    /// The implementation `name` of `slot`, or null.
    const ShaderFunction* find(const std::string& slot, const std::string& name) const;
    /// Names of the implementations of `slot`.
    std::vector<std::string> names(const std::string& slot) const;

    /// Directories searched for GLSL files, first match wins: $VOLREN_SHADER_PATH
    /// (colon-separated), then the installed shaders/ folder.
    std::vector<std::string> shaderDirectories() const;
    /// Full path of shader file `relative`; throws std::runtime_error when not found.
    std::string locate(const std::string& relative) const;

private:
    std::map<std::string, std::map<std::string, ShaderFunction>> _functions;
};

/// Registers the built-in implementations (one function per slot, in src/functions/).
void registerRaySetupFunctions(ShaderFunctionRegistry& registry);
void registerClipRayFunctions(ShaderFunctionRegistry& registry);
void registerJitterFunctions(ShaderFunctionRegistry& registry);
void registerRayTraversalFunctions(ShaderFunctionRegistry& registry);
void registerClipPositionFunctions(ShaderFunctionRegistry& registry);
void registerReconstructionFunctions(ShaderFunctionRegistry& registry);
void registerClassificationFunctions(ShaderFunctionRegistry& registry);
void registerShadingFunctions(ShaderFunctionRegistry& registry);

}  // namespace volren
