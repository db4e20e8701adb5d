#pragma once
// Internal to the reference renderer: the integral of the emission-absorption model along one
// ray through every medium of a scene, with step halving until it converges.
#include "Medium.h"

#include <vector>

namespace volren::reference {

/// The ray of one pixel in world space, from the near to the far plane.
struct Ray
{
    glm::dvec3 origin, direction;  ///< point at the near plane; far - near
    double length = 0.0;           ///< |far - near| in world units
};

/// The scene's media, clips and lights as the reference integrates them.
class Integrator
{
public:
    Integrator(const ReferenceScene& scene, const ReferenceCamera& camera, const ReferenceOptions& options);

    /// Premultiplied RGBA of one ray (before the background) up to the fraction `end` of it,
    /// converged as the options say; `finest` takes the smallest step used (shadow rays' too);
    /// `shadowsConverged` says whether every shadow ray of the integration kept converged.
    glm::dvec4 integrate(const Ray& ray, double end, bool& converged, bool& shadowsConverged, double& finest) const;

    /// What reaches the opaque geometry at `world` of its lights: the product over the media
    /// that shadow it (Medium::shadowsGeometry) of their lightOnGeometry(); 1 for none.
    double lightOnGeometry(const glm::dvec3& world, ShadowTally& tally) const;

private:
    /// Where the ray is inside the box of `m`, as fractions [a, b] of the ray; false if nowhere.
    static bool boxSpan(const Medium& m, const Ray& ray, double& a, double& b);
    /// Front-to-back over [u0, u1] of the ray with `step` world units, sampled at step midpoints;
    /// its shadow rays add to `tally`.
    glm::dvec4 march(const Ray& ray, double u0, double u1, double step, ShadowTally& tally) const;
    /// Whether every clip shape keeps world point `p`.
    bool kept(const glm::dvec3& p) const;

    ReferenceOptions _options;
    std::vector<Medium> _media;
    std::vector<Clip> _clips;  ///< from world coordinates
    double _unit = 1.0;
};

}  // namespace volren::reference
