#pragma once
#include <volume_renderer/AuxKind.h>
#include <volume_renderer/ShaderFunction.h>

#include <map>
#include <string>
#include <vector>

namespace volren {

/// Every known shader-function implementation, by slot and name.
/// Besides the built-ins it takes, at first use of instance():
/// - plugin libraries `volren_functions_*.so` in the folders of $VOLREN_FUNCTION_PATH
///   (colon-separated), each exporting `extern "C" void volrenRegisterShaderFunctions(
///   volren::ShaderFunctionRegistry&)`;
/// - GLSL files `<Slot>/<name>.glsl` in the folders of $VOLREN_SHADER_PATH that name no
///   registered implementation and that no registered implementation includes: they become
///   implementations that bind nothing (they may
///   declare their own uniforms and use any the composition declares).
class ShaderFunctionRegistry
{
public:
    /// The process-wide registry, filled with the built-ins and the run-time additions.
    static ShaderFunctionRegistry& instance();
    /// Registers every built-in implementation.
    void addBuiltins();
    /// Loads plugin libraries from $VOLREN_FUNCTION_PATH; returns the messages of failures.
    std::vector<std::string> loadPlugins();
    /// Registers unclaimed GLSL files found in $VOLREN_SHADER_PATH; returns how many.
    std::size_t addShaderDirectoryFunctions();

    /// Adds or replaces an implementation (plugins may add their own); an empty `file` becomes
    /// `<slot>/<name>.glsl`. Declares its parameters in the ParameterCatalog: throws
    /// std::logic_error when a key is taken by another parameter.
    void add(ShaderFunction function);
    /// Declares a parameter every implementation of `slot` (but null) reads; throws as add().
    void addSlotParameter(const std::string& slot, ParameterDecl parameter);
    /// The implementation `name` of `slot`, or null.
    const ShaderFunction* find(const std::string& slot, const std::string& name) const;
    /// Declares a kind of auxiliary data; throws std::logic_error when its name is taken or it
    /// says neither how it is made nor where (a Volume kind with no provide and no build).
    void addAuxKind(AuxKind kind);
    /// The kind of auxiliary data `name`, or null.
    const AuxKind* auxKind(const std::string& name) const;
    /// The kinds `function` needs; throws std::runtime_error naming the implementation and the
    /// kind when one is not declared.
    std::vector<const AuxKind*> auxKindsOf(const ShaderFunction& function) const;
    /// Whether a kind `function` needs darkens the opaque geometry (AuxKind::darkensGeometry).
    bool darkensGeometry(const ShaderFunction& function) const;
    /// Messages for the kinds implementations need that no one declared.
    std::vector<std::string> undeclaredNeeds() const;
    /// Names of the implementations of `slot` that single-volume compositions may choose (the
    /// multi-volume set functions are left out).
    std::vector<std::string> names(const std::string& slot) const;
    /// Names of every implementation of `slot`, the multi-volume set functions included.
    std::vector<std::string> allNames(const std::string& slot) const;

    /// Directories searched for GLSL files, first match wins: $VOLREN_SHADER_PATH
    /// (colon-separated), then the installed shaders/ folder.
    std::vector<std::string> shaderDirectories() const;
    /// Full path of shader file `relative`; throws std::runtime_error when not found.
    std::string locate(const std::string& relative) const;
    /// Text of shader file `relative` (located as locate() does); throws std::runtime_error
    /// naming the file when it is missing or unreadable.
    std::string read(const std::string& relative) const;

private:
    std::map<std::string, std::map<std::string, ShaderFunction>> _functions;
    std::map<std::string, AuxKind> _auxKinds;
};

/// Registers the built-in implementations (one function and file per slot, src/functions/<Slot>.cpp).
void registerRaySetupFunctions(ShaderFunctionRegistry& registry);
void registerClipRayFunctions(ShaderFunctionRegistry& registry);
void registerJitterFunctions(ShaderFunctionRegistry& registry);
void registerRayTraversalFunctions(ShaderFunctionRegistry& registry);
void registerClipPositionFunctions(ShaderFunctionRegistry& registry);
void registerReconstructionFunctions(ShaderFunctionRegistry& registry);
void registerVolumeStorageFunctions(ShaderFunctionRegistry& registry);
void registerClassificationFunctions(ShaderFunctionRegistry& registry);
void registerShadingFunctions(ShaderFunctionRegistry& registry);
void registerGradientFunctions(ShaderFunctionRegistry& registry);
void registerGradientInputFunctions(ShaderFunctionRegistry& registry);
void registerIlluminationFunctions(ShaderFunctionRegistry& registry);
void registerShadowingFunctions(ShaderFunctionRegistry& registry);
void registerAccelerationFunctions(ShaderFunctionRegistry& registry);
void registerWeightingFunctions(ShaderFunctionRegistry& registry);
/// The set traversal (RayTraversal "sum_of_media") and per-member glue (MultiVolume "member")
/// of multi-volume set programs.
void registerMultiVolumeFunctions(ShaderFunctionRegistry& registry);

}  // namespace volren
