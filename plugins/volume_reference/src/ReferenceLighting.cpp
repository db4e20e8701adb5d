// The reference's lighting: the Shading, Illumination and Shadowing models the renderer's
// implementations are checked against, chosen per volume from the renderer's choices or the
// node's settings.
#include "Medium.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace volren::reference {

glm::dvec3 Medium::shade(const glm::dvec3& tc, const glm::dvec3& local, const glm::dvec3& view, const glm::dvec3& albedo,
                         double alpha, ShadowTally& tally) const
{
    if (shading == Shading::None || (shading == Shading::Threshold && alpha < shadingThreshold)) return albedo;
    glm::dvec3 gradient;
    if (gradientKind == ReferenceOptions::Gradient::CentralDifferences) gradient = centralDifferences(tc);
    else value(tc, &gradient);
    const double scale = std::max({std::abs(gradient.x), std::abs(gradient.y), std::abs(gradient.z)});
    // A gradient too small for a direction (as the GPU's volren_normalFromGradient: largest
    // component <= 1e-30), infinite or NaN: the view direction.
    glm::dvec3 normal = scale > 1e-30 && std::isfinite(scale) ? -glm::normalize(gradient / scale) : view;
    if (glm::dot(normal, view) < 0.0) normal = -normal;  // two-sided: normals face the viewer
    glm::dvec3 colour = ambient * albedo;
    if (occlusion && colour != glm::dvec3(0.0)) colour *= ambientOcclusion(local, normal, tally);  // none for no light
    for (const auto& [position, lightColour] : lights) {
        const glm::dvec3 toLight = position.w == 0.0 ? glm::dvec3(position) : glm::dvec3(position) - local;
        const double length = glm::length(toLight);
        if (!(length > 0.0)) continue;
        const glm::dvec3 term = lightColour * illuminate(normal, view, toLight / length, albedo);
        // Exact shadows: the light's term times the transmittance to it (none where it adds nothing).
        if (shadows == ReferenceScene::Shadows::None || term == glm::dvec3(0.0)) colour += term;
        else if (blocked(local, position)) continue;  // opaque geometry in the way
        else
            colour += term * transmittance(local, toLight / length,
                                           position.w == 0.0 ? std::numeric_limits<double>::infinity() : length, tally);
    }
    if (shading != Shading::Surface) return colour;
    // lighting_surface: lit by w = 1 - exp(-|g| / (0.05 G)), G = the TF window per smallest spacing.
    const double surfaceGradient = 0.05 * (domainMax - domainMin) / unitLength;
    double w = surfaceGradient > 0.0 ? -std::expm1(-glm::length(gradient) / surfaceGradient) : 1.0;
    if (!(w >= 0.0)) w = 1.0;  // a non-finite gradient: lit, as its normal is
    return albedo + w * (colour - albedo);
}

glm::dvec3 Medium::illuminate(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& albedo) const
{
    const double nl = glm::dot(n, l);
    switch (illumination) {
    case Illumination::None: return glm::dvec3(0.0);
    case Illumination::Lambert: return albedo * std::max(nl, 0.0);
    case Illumination::BlinnPhong: {
        if (!(nl > 0.0)) return glm::dvec3(0.0);
        const glm::dvec3 halfway = l + v;
        const double h = glm::length(halfway);
        const double highlight = h > 1e-12 ? std::pow(std::max(glm::dot(n, halfway / h), 0.0), shininess) : 0.0;
        return albedo * nl + glm::dvec3(specular * highlight);
    }
    case Illumination::CookTorrance: {
        // GGX distribution, Smith-Schlick geometry (k = a/2), Schlick Fresnel with F0 = 0.04.
        if (!(nl > 0.0)) return glm::dvec3(0.0);
        const double nv = std::max(glm::dot(n, v), 1e-4);
        const glm::dvec3 halfway = l + v;
        const double len = glm::length(halfway);
        const glm::dvec3 h = len > 1e-12 ? halfway / len : n;
        const double nh = std::max(glm::dot(n, h), 0.0), vh = std::max(glm::dot(v, h), 0.0);
        const double a = std::max(roughness * roughness, 1e-4), a2 = a * a;
        const double d = nh * nh * (a2 - 1.0) + 1.0;
        const double distribution = a2 / (M_PI * d * d);
        const double k = a * 0.5;
        const double geometry = (nl / (nl * (1.0 - k) + k)) * (nv / (nv * (1.0 - k) + k));
        const double fresnel = 0.04 + 0.96 * std::pow(1.0 - vh, 5.0);
        return albedo * nl + glm::dvec3(specular * distribution * geometry * fresnel / (4.0 * nl * nv) * nl);
    }
    }
    return glm::dvec3(0.0);
}

namespace {

/// The implementation of `slot` for a volume: the renderer's choice when given, else the node's
/// own (forced null, chosen, or null when unset).
std::string choiceOf(const ReferenceScene::Placed& placed, const RenderSettings& s, const std::string& slot)
{
    if (auto it = placed.choice.find(slot); it != placed.choice.end()) return it->second;
    if (s.forceNull.count(slot)) return "null";
    auto it = s.functions.find(slot);
    return it == s.functions.end() ? "null" : it->second;
}

}  // namespace

void setShading(Medium& m, const ReferenceScene::Placed& placed, bool lit)
{
    const auto& node = static_cast<const VolumeNode&>(*placed.node);
    const RenderSettings& s = node.settings;
    const bool decided = !placed.choice.empty();
    const std::string illumination = decided || lit ? choiceOf(placed, s, "Illumination") : "null";
    const std::string shading = decided || lit ? choiceOf(placed, s, "Shading") : "null";
    if (shading == "null") m.shading = Shading::None;
    else if (shading == "lighting") m.shading = Shading::Lighting;
    else if (shading == "lighting_threshold") m.shading = Shading::Threshold;
    else if (shading == "lighting_surface") m.shading = Shading::Surface;
    else throw std::invalid_argument("reference: no model for Shading '" + shading + "' (volume '" + node.getName() + "')");
    if (illumination == "null") m.illumination = Illumination::None;
    else if (illumination == "lambert") m.illumination = Illumination::Lambert;
    else if (illumination == "blinn_phong") m.illumination = Illumination::BlinnPhong;
    else if (illumination == "cook_torrance") m.illumination = Illumination::CookTorrance;
    else
        throw std::invalid_argument("reference: no model for Illumination '" + illumination + "' (volume '" +
                                    node.getName() + "')");
    if (placed.shadows) {
        m.shadows = *placed.shadows;
    } else {
        const std::string shadowing = decided || lit ? choiceOf(placed, s, "Shadowing") : "null";
        if (shadowing == "null") m.shadows = ReferenceScene::Shadows::None;
        else if (shadowing == "ray") m.shadows = ReferenceScene::Shadows::Exact;  // the definition itself
        else
            throw std::invalid_argument("reference: no model for Shadowing '" + shadowing + "' (volume '" +
                                        node.getName() + "'; Placed::shadows may say which it approximates)");
    }
    // Ambient occlusion from the cones' start to their reach, in voxels of the smallest extent.
    m.occlusion = (decided || lit) && placed.occlusion;
    const double voxel = std::min({m.size.x / m.dims.x, m.size.y / m.dims.y, m.size.z / m.dims.z});
    m.occlusionStart = s.number("coneStart") * voxel;
    m.occlusionDistance = s.number("aoDistance") * voxel;
    m.ambient = s.number("ambient");
    m.specular = s.number("specular");
    m.shininess = s.number("shininess");
    m.roughness = s.number("roughness");
    m.shadingThreshold = s.number("shadingThreshold");
}

void setWeighting(Medium& m, const ReferenceScene::Placed& placed)
{
    const auto& node = static_cast<const VolumeNode&>(*placed.node);
    const RenderSettings& s = node.settings;
    const SpatialWeighting curves = spatialWeighting(s);
    const std::string weighting = !placed.choice.empty() ? choiceOf(placed, s, "Weighting")
                                  : s.forceNull.count("Weighting") || curves.identity()
                                      ? "null"
                                      : s.functions.count("Weighting") ? s.functions.at("Weighting")
                                                                       : "axes";
    if (weighting == "null") m.weighting = {};
    else if (weighting == "axes") m.weighting = curves;
    else
        throw std::invalid_argument("reference: no model for Weighting '" + weighting + "' (volume '" + node.getName() +
                                    "')");
}

}  // namespace volren::reference
