// The reference's lighting: the Shading, Illumination and Shadowing models the renderer's
// implementations are checked against, chosen per volume from the renderer's choices or the
// node's settings, by the models those implementations declare (ReferenceModelCatalog).
#include "Medium.h"

#include <volume_model/ReferenceModel.h>

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
    glm::dvec3 gradient(0.0);  // zeroGradient: stays zero
    if (!zeroGradient && gradientKind == ReferenceOptions::Gradient::CentralDifferences) gradient = centralDifferences(tc);
    else if (!zeroGradient) value(tc, &gradient);
    const double scale = std::max({std::abs(gradient.x), std::abs(gradient.y), std::abs(gradient.z)});
    // A gradient too small for a direction (as the GPU's volren_normalFromGradient: largest
    // component <= 1e-30), infinite or NaN: the view direction.
    // (std::max may pass over a NaN component: a NaN voxel among the gradient's taps.)
    const bool nan = std::isnan(gradient.x) || std::isnan(gradient.y) || std::isnan(gradient.z);
    glm::dvec3 normal = !nan && scale > 1e-30 && std::isfinite(scale) ? -glm::normalize(gradient / scale) : view;
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
    // A NaN gradient (a NaN voxel among its taps) tells nothing of a boundary: unlit, as the GPU's
    // Shading/lighting_surface; an infinite one is the steepest boundary: lit.
    if (std::isnan(w)) w = 0.0;
    return albedo + w * (colour - albedo);
}

glm::dvec3 Medium::illuminate(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& albedo) const
{
    const double nl = glm::dot(n, l);
    switch (illumination) {
    case Illumination::None: return glm::dvec3(0.0);
    case Illumination::Lambert: return albedo * std::max(nl, 0.0);
    case Illumination::HenyeyGreenstein: {
        // Light travelling along -l scattered towards the viewer along v, scaled by 4 pi so that
        // g = 0 (isotropic) gives the albedo: (1 - g^2) / (1 + g^2 - 2 g cos)^(3/2).
        const double g = anisotropy, cosTheta = glm::dot(-l, v);
        const double denominator = std::max(1.0 + g * g - 2.0 * g * cosTheta, 1e-12);
        return albedo * ((1.0 - g * g) / (denominator * std::sqrt(denominator)));
    }
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

/// The model implementation `name` of `slot` declares (ReferenceModelCatalog), one the reference
/// implements; throws naming the implementation, the volume and why there is none.
std::string declaredModel(const std::string& slot, const std::string& name, const VolumeNode& node)
{
    const std::string what = slot + " '" + name + "' (volume '" + node.getName() + "')";
    const ReferenceModel* model = ReferenceModelCatalog::instance().find(slot, name);
    if (!model) throw std::invalid_argument("reference: no model for " + what + ": it declares none");
    if (model->fidelity == ReferenceModel::Fidelity::None)
        throw std::invalid_argument("reference: no model for " + what + ": " + model->why);
    const std::vector<std::string>& known = ReferenceScene::models().at(slot);
    if (std::find(known.begin(), known.end(), model->model) == known.end())
        throw std::invalid_argument("reference: " + what + " declares the model '" + model->model +
                                    "', which the reference does not implement");
    return model->model;
}

}  // namespace

void setShading(Medium& m, const ReferenceScene::Placed& placed, bool lit)
{
    const auto& node = static_cast<const VolumeNode&>(*placed.node);
    const RenderSettings& s = node.settings;
    const bool decided = !placed.choice.empty();
    const bool shaded = decided || lit;
    static const std::map<std::string, Shading> shadings = {{"unlit", Shading::None},
                                                            {"lit", Shading::Lighting},
                                                            {"lit above threshold", Shading::Threshold},
                                                            {"lit on surfaces", Shading::Surface}};
    static const std::map<std::string, Illumination> illuminations = {
        {"no light", Illumination::None},
        {"lambert diffuse", Illumination::Lambert},
        {"diffuse + blinn-phong highlight", Illumination::BlinnPhong},
        {"diffuse + cook-torrance ggx highlight", Illumination::CookTorrance},
        {"henyey-greenstein phase", Illumination::HenyeyGreenstein}};
    m.shading = shaded ? shadings.at(declaredModel("Shading", choiceOf(placed, s, "Shading"), node)) : Shading::None;
    m.illumination = shaded ? illuminations.at(declaredModel("Illumination", choiceOf(placed, s, "Illumination"), node))
                            : Illumination::None;
    if (placed.shadows) {
        m.shadows = *placed.shadows;
    } else {
        const std::string shadowing = shaded ? declaredModel("Shadowing", choiceOf(placed, s, "Shadowing"), node) : "unshadowed";
        m.shadows = shadowing == "unshadowed" ? ReferenceScene::Shadows::None : ReferenceScene::Shadows::Exact;
    }
    // Ambient occlusion from the cones' start to their reach, in voxels of the smallest extent.
    m.occlusion = shaded && placed.occlusion;
    const double voxel = std::min({m.size.x / m.dims.x, m.size.y / m.dims.y, m.size.z / m.dims.z});
    m.occlusionStart = s.number("coneStart") * voxel;
    m.occlusionDistance = s.number("aoDistance") * voxel;
    // The renderer's Gradient, where it chose one: none gives a zero gradient.
    if (auto it = placed.choice.find("Gradient"); shaded && it != placed.choice.end())
        m.zeroGradient = declaredModel("Gradient", it->second, node) == "no gradient";
    m.ambient = s.number("ambient");
    m.specular = s.number("specular");
    m.shininess = s.number("shininess");
    m.roughness = s.number("roughness");
    m.shadingThreshold = s.number("shadingThreshold");
    m.anisotropy = s.number("anisotropy");
}

void setWeighting(Medium& m, const ReferenceScene::Placed& placed)
{
    const auto& node = static_cast<const VolumeNode&>(*placed.node);
    const RenderSettings& s = node.settings;
    const SpatialWeighting curves = spatialWeighting(s);
    // Undecided and unnamed: weighted by the node's curves where it has any, as the policy does.
    const bool own = placed.choice.empty() && !s.forceNull.count("Weighting") && !s.functions.count("Weighting");
    const std::string model = own ? (curves.identity() ? "unweighted" : "axis curves")
                                  : declaredModel("Weighting", choiceOf(placed, s, "Weighting"), node);
    m.weighting = model == "axis curves" ? curves : SpatialWeighting{};
}

}  // namespace volren::reference
