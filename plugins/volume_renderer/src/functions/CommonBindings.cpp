#include "CommonBindings.h"

#include <volume_renderer/BrickPool.h>
#include <volume_renderer/VolumeMipChain.h>

#include <volume_model/ParameterCatalog.h>
#include <volume_model/RenderSettings.h>
#include <volume_model/SpatialWeighting.h>
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>
#include <volume_model/VolumeNode.h>

#include <cmath>

namespace volren::bindings {

const std::vector<UniformDecl> geometry = {{"volren_worldSize", "vec3", ""}, {"volren_dims", "vec3", ""}};

void bindGeometry(BindContext& c)
{
    // The voxels of the level sampled: its texture's, or for bricks that level's (a lazy
    // volume's levels are its file's, not those of the coarse level in RAM).
    const osg::Vec3i d = c.bricks ? c.bricks->layout.levels.at(std::size_t(c.lod)).dims : mipDims(c.volume.dims(), c.lod);
    c.uniform("volren_worldSize", osg::Vec3f(c.boxSize.length2() > 0.0 ? c.boxSize : c.volume.worldSize()));
    c.uniform("volren_dims", osg::Vec3f(float(d.x()), float(d.y()), float(d.z())));
}

const std::vector<UniformDecl> window = {{"volren_window", "vec3", ""}, {"volren_tfResolution", "float", ""}};

std::pair<double, double> windowOf(const BindContext& c)
{
    return {c.transfer.domainMin(), c.transfer.domainMax()};
}

std::pair<double, double> windowMap(const BindContext& c)
{
    // texel v -> stored v*norm -> data stored*slope + intercept -> window (data - lo)/(hi - lo).
    const double norm = normalisedScale(c.volume.type());
    const auto [lo, hi] = windowOf(c);
    return {norm * c.volume.rescaleSlope() / (hi - lo), (c.volume.rescaleIntercept() - lo) / (hi - lo)};
}

void bindWindow(BindContext& c)
{
    const auto [scale, offset] = windowMap(c);
    // The scale in two factors where it would be a denormal float (a window wider than 2^100:
    // float data up to float's largest), which GPUs flush to zero: v * (scale * 2^64) * 2^-64.
    const bool tiny = std::abs(scale) > 0.0 && std::abs(scale) < std::ldexp(1.0, -100);
    const double split = tiny ? std::ldexp(1.0, -64) : 1.0;
    c.uniform("volren_window", osg::Vec3f(float(scale / split), float(offset), float(split)));
    c.uniform("volren_tfResolution", float(c.transfer.resolution()));
}

const TextureDecl volumeTexture = {"volren_volume", "sampler3D"};

void bindVolumeTexture(BindContext& c)
{
    c.texture("volren_volume", c.aux.at("volume texture").get());
}

const std::vector<UniformDecl> lights = {
    {.name = "volren_lightPosition", .glslType = "vec4", .arraySize = "VOLREN_LIGHT_ARRAY", .perLight = true},
    {.name = "volren_lightColour", .glslType = "vec3", .arraySize = "VOLREN_LIGHT_ARRAY", .perLight = true},
    {"volren_ambient", "float", ""}};

void bindLights(BindContext& c)
{
    const unsigned int size = std::max<unsigned int>(1, unsigned(c.lights.size()));
    for (unsigned int i = 0; i < size; ++i) {
        const LightInfo light = i < c.lights.size() ? c.lights[i] : LightInfo{};
        c.uniformElement("volren_lightPosition", size, i, osg::Vec4f(light.position));
        c.uniformElement("volren_lightColour", size, i, osg::Vec3f(light.colour));
    }
    c.uniform("volren_ambient", float(c.settings.number("ambient")));
}

const UniformDecl gradientScale = {"volren_gradientScale", "float", ""};

void bindGradientScale(BindContext& c)
{
    double range = 1.0;  // classified alpha spans [0,1]
    auto input = c.chosen.find("GradientInput");
    if (input == c.chosen.end() || input->second != "alpha") {
        const auto [lo, hi] = windowOf(c);
        range = (hi - lo) / (c.volume.rescaleSlope() * normalisedScale(c.volume.type()));  // in texel units
    }
    c.uniform("volren_gradientScale", float(std::abs(range) / c.volume.minSpacing()));
}

std::vector<UniformDecl> operator+(std::vector<UniformDecl> a, const std::vector<UniformDecl>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

void appendParameterValues(std::string& key, const RenderSettings& settings, const ShaderFunction& function)
{
    for (const ParameterDecl& p : ParameterCatalog::instance().all()) {
        if (!p.readBy(function.slot, function.name)) continue;
        switch (p.type) {
        case ParameterType::Number: appendBytes(key, settings.number(p.key)); break;
        case ParameterType::Integer: appendBytes(key, settings.parameter<int>(p.key)); break;
        case ParameterType::Switch: appendBytes(key, settings.parameter<bool>(p.key)); break;
        case ParameterType::Choice: key += settings.parameter<std::string>(p.key) + '\0'; break;
        case ParameterType::Curve:
            appendBytes(key, settings.parameter<WeightCurve>(p.key).knots.size());
            for (const auto& [u, w] : settings.parameter<WeightCurve>(p.key).knots) {
                appendBytes(key, u);
                appendBytes(key, w);
            }
            break;
        }
    }
}

}  // namespace volren::bindings
