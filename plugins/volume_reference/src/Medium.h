#pragma once
// Internal to the reference renderer: one volume as the integrator samples it (the trilinear
// field, its gradients, the transfer function) and how its samples are lit.
#include <volume_reference/ReferenceRenderer.h>

#include <glm/glm.hpp>
#include <osg/Matrixd>

#include <utility>
#include <vector>

namespace volren::reference {

inline glm::dvec3 toGlm(const osg::Vec3d& v) { return {v.x(), v.y(), v.z()}; }

/// How a medium's samples are lit (the node's Shading and Illumination choices).
enum class Shading { None, Lighting, Threshold, Surface };
enum class Illumination { None, Lambert, BlinnPhong, CookTorrance };

/// The trilinear cell of a texture coordinate along each axis: the two voxel indices, their
/// weights, and d(weight of the upper voxel)/d(local unit) (0 where the field is clamped).
struct Cell
{
    int i[3][2];
    double w[3][2];
    double slope[3];

    Cell(const glm::dvec3& tc, const glm::ivec3& dims, const glm::dvec3& size);
    double weight(int dx, int dy, int dz) const { return w[0][dx] * w[1][dy] * w[2][dz]; }
};

/// One volume as the integrator needs it.
struct Medium
{
    const Volume* volume = nullptr;
    const TransferFunction* tf = nullptr;
    osg::Matrixd worldToLocal;
    glm::dvec3 size;       ///< box size (world units of the node's frame)
    glm::ivec3 dims;
    double unitLength = 1.0;  ///< Δ0: the smallest voxel spacing; TF alpha is per this length
    double domainMin = 0.0, domainMax = 1.0;
    Shading shading = Shading::None;
    Illumination illumination = Illumination::None;
    double ambient = 0.0, specular = 0.0, shininess = 1.0, roughness = 1.0, shadingThreshold = 0.0;
    /// Lights in the node's local coordinates: position (w = 0: direction towards the light) and colour.
    std::vector<std::pair<glm::dvec4, glm::dvec3>> lights;
    ReferenceOptions::Gradient gradientKind = ReferenceOptions::Gradient::CentralDifferences;

    /// Trilinear interpolation of the grid's central differences (per local unit) at `tc`.
    glm::dvec3 centralDifferences(const glm::dvec3& tc) const;
    /// Trilinear data value at texture coordinate `tc` ([0,1]^3; voxel centres at (i+0.5)/n),
    /// and, when `gradient` is given, its exact gradient per local (world) unit; zero along an
    /// axis where the field is clamped (outside the outermost voxel centres).
    double value(const glm::dvec3& tc, glm::dvec3* gradient = nullptr) const;
    /// Emitted colour of a sample of TF colour `albedo` and opacity `alpha` at `tc` (local point
    /// `local`), seen along `view` (unit, towards the eye, local axes).
    glm::dvec3 shade(const glm::dvec3& tc, const glm::dvec3& local, const glm::dvec3& view, const glm::dvec3& albedo,
                     double alpha) const;
    /// Light reflected towards `v` from a unit light from `l` by a surface of normal `n`.
    glm::dvec3 illuminate(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& albedo) const;
};

/// Sets how `m` is lit from the volume's choices (the renderer's, or the node's own when lights
/// reach it: `lit`); throws std::invalid_argument for a Shading or Illumination it has no model of.
void setShading(Medium& m, const ReferenceScene::Placed& placed, bool lit);

}  // namespace volren::reference
