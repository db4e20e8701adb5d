#pragma once
// Internal to the reference renderer: one volume as the integrator samples it (the trilinear
// field, its gradients, the transfer function), how its samples are lit and what shadows them.
#include <volume_model/ClipNode.h>
#include <volume_model/SpatialWeighting.h>
#include <volume_reference/ReferenceRenderer.h>

#include <glm/glm.hpp>
#include <osg/Matrixd>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace volren::reference {

inline glm::dvec3 toGlm(const osg::Vec3d& v) { return {v.x(), v.y(), v.z()}; }

/// How a medium's samples are lit (the node's Shading and Illumination choices).
enum class Shading { None, Lighting, Threshold, Surface };
enum class Illumination { None, Lambert, BlinnPhong, CookTorrance, HenyeyGreenstein };

/// A clip shape and the transform into its own coordinates (from world in the integrator, from
/// the medium's local coordinates in a Medium).
struct Clip
{
    const ClipNode* node;
    osg::Matrixd toShape;
};

/// What the shadow rays of one march needed: whether every one reached its tolerance, and the
/// smallest step any took (world units).
struct ShadowTally
{
    bool converged = true;
    double finest = std::numeric_limits<double>::infinity();
};

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
    /// The factor on each sample's TF opacity by its texture coordinate (Weighting axes; all 1
    /// for null): classify() applies it, maxima count only samples it weighs above 0.
    SpatialWeighting weighting;
    Shading shading = Shading::None;
    Illumination illumination = Illumination::None;
    double ambient = 0.0, specular = 0.0, shininess = 1.0, roughness = 1.0, shadingThreshold = 0.0;
    double anisotropy = 0.0;  ///< Henyey-Greenstein g
    /// Lights in the node's local coordinates: position (w = 0: direction towards the light) and colour.
    std::vector<std::pair<glm::dvec4, glm::dvec3>> lights;
    ReferenceOptions::Gradient gradientKind = ReferenceOptions::Gradient::CentralDifferences;
    /// Drawn with no Gradient (the renderer's choice declares "no gradient"): every gradient is
    /// zero, so normals face the viewer and lighting_surface leaves samples unlit.
    bool zeroGradient = false;
    /// Shadows of lit samples (Exact: each light's term times the transmittance to it through
    /// this medium, clipped as `clips` say), and how their rays converge: steps from
    /// shadowFirstStep x Δ0 halved until two transmittances differ by at most shadowTolerance,
    /// or the step reaches shadowFinestStep x Δ0.
    ReferenceScene::Shadows shadows = ReferenceScene::Shadows::None;
    double shadowTolerance = 2.5e-5, shadowFirstStep = 0.25, shadowFinestStep = 1.0 / 4096.0;
    /// Ambient occlusion (Shadowing cone_ao): the ambient term scaled by (1/pi) times the
    /// integral over the hemisphere around the normal of the transmittance from occlusionStart to
    /// occlusionDistance (local lengths) along each direction, weighted by its cosine. A fixed
    /// quadrature (ReferenceOptions::occlusionDirections, occlusionStep), so that the estimate
    /// is a continuous function of the sample's position and the view ray converges over it.
    bool occlusion = false;
    double occlusionStart = 0.0, occlusionDistance = 0.0;
    int occlusionDirections = 12;   ///< strata per side of the unit square: their square in all
    double occlusionStep = 0.25;    ///< each direction's march step, in Δ0
    /// It shadows the opaque geometry (ReferenceScene::Placed::shadowsGeometry; lit media only).
    bool shadowsGeometry = false;
    osg::Matrixd localToWorld;
    std::vector<Clip> clips;  ///< the clip shapes that apply, from local coordinates
    /// With exact shadows: the scene whose opaque triangles (ReferenceScene::occluders) block a
    /// light wholly where they cross the way from the sample to it; null: none.
    const ReferenceScene* occluders = nullptr;
    /// Shadow rays' empty-space test, per block of 4^3 trilinear cells: whether the TF gives
    /// every value the field takes there opacity 0 (their samples would add nothing).
    std::vector<unsigned char> emptyBlocks;
    glm::ivec3 blockCount{0, 0, 0};

    /// Trilinear interpolation of the grid's central differences (per local unit) at `tc`.
    glm::dvec3 centralDifferences(const glm::dvec3& tc) const;
    /// Trilinear data value at texture coordinate `tc` ([0,1]^3; voxel centres at (i+0.5)/n),
    /// and, when `gradient` is given, its exact gradient per local (world) unit; zero along an
    /// axis where the field is clamped (outside the outermost voxel centres).
    double value(const glm::dvec3& tc, glm::dvec3* gradient = nullptr) const;
    /// The TF's colour and opacity at `tc`, the opacity scaled by the weighting there; false where
    /// the medium is empty (a NaN value, or opacity 0). The view ray's and shadow rays' medium alike.
    bool classify(const glm::dvec3& tc, osg::Vec4& rgba) const;
    /// Extinction per length unit of a sample of TF opacity `alpha` in (0, 1): -ln(1 - α) / Δ0.
    double extinction(double alpha) const { return -std::log1p(-alpha) / unitLength; }
    /// Emitted colour of a sample of TF colour `albedo` and opacity `alpha` at `tc` (local point
    /// `local`), seen along `view` (unit, towards the eye, local axes); shadow rays add to `tally`.
    glm::dvec3 shade(const glm::dvec3& tc, const glm::dvec3& local, const glm::dvec3& view, const glm::dvec3& albedo,
                     double alpha, ShadowTally& tally) const;
    /// Transmittance from local point `local` along the unit local direction `l` over
    /// min(`distance`, the way out of the box): exp(-the integral of the extinction, in world
    /// lengths as the view ray's), converged; 0 past an opaque (α >= 1) point, 1 for no path.
    double transmittance(const glm::dvec3& local, const glm::dvec3& l, double distance, ShadowTally& tally) const;
    /// The mean over the lights of the transmittance from local point `local` (inside or
    /// outside the box) to each light through this medium.
    double lightOnGeometry(const glm::dvec3& local, ShadowTally& tally) const;
    /// Whether opaque geometry blocks the way from local point `local` to the light at local
    /// `position` (w = 0: the direction towards it).
    bool blocked(const glm::dvec3& local, const glm::dvec4& position) const;
    /// The ambient occlusion at local point `local` around the unit `normal` (see `occlusion`).
    double ambientOcclusion(const glm::dvec3& local, const glm::dvec3& normal, ShadowTally& tally) const;
    /// Fills emptyBlocks from the volume and the TF.
    void findEmptyBlocks();
    /// Whether `tc` lies in an empty block (false when there are none).
    bool inEmptyBlock(const glm::dvec3& tc) const;
    /// Light reflected towards `v` from a unit light from `l` by a surface of normal `n`.
    glm::dvec3 illuminate(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& albedo) const;
};

/// Sets how `m` is lit from the volume's choices (the renderer's, or the node's own when lights
/// reach it: `lit`): Shading, Illumination, and shadows (Placed::shadows, else from Shadowing);
/// throws std::invalid_argument for a Shading, Illumination or Shadowing it has no model of.
void setShading(Medium& m, const ReferenceScene::Placed& placed, bool lit);
/// Sets `m`'s spatial weighting from the volume's Weighting choice (the renderer's; undecided:
/// the node's weighting unless Weighting is forced null); throws std::invalid_argument for a
/// Weighting it has no model of.
void setWeighting(Medium& m, const ReferenceScene::Placed& placed);

}  // namespace volren::reference
