#pragma once
// Uniforms several implementations share: declared by each that reads them (the compositor
// declares a name once) and set by these helpers, so their values have one definition.
#include <volume_renderer/ShaderFunction.h>

#include <string>

namespace volren::bindings {

/// volren_worldSize (vec3) and volren_dims (vec3).
extern const std::vector<UniformDecl> geometry;
void bindGeometry(BindContext& c);

/// volren_window (vec3: texel value v -> TF window [0,1] as v * x * z + y, the scale split
/// into x * z where it would be a denormal float) and volren_tfResolution (float).
extern const std::vector<UniformDecl> window;
void bindWindow(BindContext& c);

/// The volume texture as volren_volume (sampler3D).
extern const TextureDecl volumeTexture;
void bindVolumeTexture(BindContext& c);

/// Scene lights: volren_lightPosition, volren_lightColour (arrays) and volren_ambient.
extern const std::vector<UniformDecl> lights;
void bindLights(BindContext& c);

/// volren_gradientScale: gradient magnitude of a jump across the whole TF window within one
/// smallest voxel spacing, in the units of the chosen GradientInput.
extern const UniformDecl gradientScale;
void bindGradientScale(BindContext& c);

/// The transfer function's value window in data units: [lo, hi].
std::pair<double, double> windowOf(const BindContext& c);

/// volren_window's value: texel value v -> window u = v * first + second (before clamping).
std::pair<double, double> windowMap(const BindContext& c);

/// Appends the bytes of `value` to `key` (a cache key of values compared, never formatted).
template <typename T>
void appendBytes(std::string& key, const T& value)
{
    key.append(reinterpret_cast<const char*>(&value), sizeof(value));
}

/// Appends to `key` the values in `settings` of every parameter `function` reads (so a cache
/// key holds what a mirror made from that implementation depends on).
void appendParameterValues(std::string& key, const RenderSettings& settings, const ShaderFunction& function);

/// Concatenation helper for uniform lists.
std::vector<UniformDecl> operator+(std::vector<UniformDecl> a, const std::vector<UniformDecl>& b);

}  // namespace volren::bindings
