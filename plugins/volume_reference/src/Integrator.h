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
    /// The ray over [u0, u1] with `step` world units: each group of overlapping media as its
    /// blending combines them, the groups front to back by where the ray enters them.
    glm::dvec4 sample(const Ray& ray, double u0, double u1, double step, ShadowTally& tally) const;
    /// Front-to-back over [u0, u1] of the ray with `step` world units, sampled at step midpoints,
    /// through the media `members` (null: every medium); its shadow rays add to `tally`.
    glm::dvec4 march(const Ray& ray, double u0, double u1, double step, ShadowTally& tally,
                     const std::vector<std::size_t>* members = nullptr) const;
    /// Medium `index`'s classified maximum over [u0, u1] of the ray (step midpoints; clipped and
    /// NaN points ignored), premultiplied; 0 where no point counts.
    glm::dvec4 maximum(const Ray& ray, double u0, double u1, double step, std::size_t index) const;
    /// Sorts the media into _groups (the scene's blending per volume).
    void groupMedia(const ReferenceScene& scene);
    /// Whether every clip shape keeps world point `p`.
    bool kept(const glm::dvec3& p) const;

    ReferenceOptions _options;
    /// Media whose world boxes overlap, transitively (the renderer's ray groups), and how each
    /// group combines; one group of every medium when all combine their media.
    struct Group
    {
        std::vector<std::size_t> members;
        ReferenceScene::Blending blending = ReferenceScene::Blending::Media;
    };
    std::vector<Group> _groups;
    std::vector<Medium> _media;
    std::vector<Clip> _clips;  ///< from world coordinates
    double _unit = 1.0;
};

}  // namespace volren::reference
