#pragma once
#include <volume_reference/ReferenceScene.h>

#include <osg/Matrixd>
#include <osg/Vec3d>

#include <cstddef>
#include <vector>

namespace volren {

/// A view to render: the matrices of an osg::Camera (clip = world * view * projection).
struct ReferenceCamera
{
    osg::Matrixd view, projection;
    int width = 64, height = 64;
};

/// How finely to integrate. Each ray starts with steps of `firstStep` x the smallest voxel
/// spacing and halves them until two successive results differ by at most `tolerance` in every
/// RGBA channel (then the finer one is kept), or the step reaches `finestStep` x that spacing.
/// Shadow rays (Shadows::Exact) do the same on their own, from `firstStep` x their volume's
/// smallest spacing (at least two steps) until two transmittances differ by at most
/// `tolerance` / 4, or the step reaches `finestStep` x that spacing.
struct ReferenceOptions
{
    double tolerance = 1e-4;
    double firstStep = 0.25;
    double finestStep = 1.0 / 4096.0;
    osg::Vec3d background{0.0, 0.0, 0.0};  ///< linear RGB behind the volumes
    /// Opaque geometry, as a rasteriser drew it for the same camera (row 0 at the bottom): its
    /// window depth per pixel (rays end there; 1 = nothing) and its premultiplied RGBA over the
    /// background (what the volumes are composited over). Empty: no geometry.
    std::vector<float> geometryDepth;
    std::vector<float> geometryColour;
    unsigned int threads = 0;               ///< 0: one per hardware thread
    /// Shade with the scene's lights (off: emission is the TF colour, as VolumeScene's
    /// `lighting=off`). Like the renderer, the first 8 lights count.
    bool lighting = true;
    /// The normals of lit samples: central differences of the trilinear field over one voxel
    /// each way (= the trilinear interpolation of the grid's central differences, clamped at the
    /// edges; the GPU's default Gradient `central`, so lit images are compared in one
    /// convention), or the exact gradient of the trilinear field (it jumps across voxel faces;
    /// on noisy data its normals differ from any smooth estimate at every surface).
    enum class Gradient { Exact, CentralDifferences } gradient = Gradient::CentralDifferences;
    /// Ambient occlusion (ReferenceScene::Placed::occlusion) by a fixed quadrature, not halved
    /// until converged (a per-sample adaptive estimate jumps from sample to sample, and the view
    /// ray then never converges): the cosine-weighted directions at the midpoints of
    /// occlusionDirections^2 strata of the unit square, each marched in steps of occlusionStep x
    /// the smallest spacing. Its own error: ReferenceShadows tests it against a finer quadrature.
    int occlusionDirections = 12;
    double occlusionStep = 0.25;
};

/// The result: RGBA in double precision, row 0 at the bottom, colour premultiplied and composited
/// over the background, alpha the volumes' coverage (as OffscreenRenderer's image).
struct ReferenceImage
{
    int width = 0, height = 0;
    std::vector<double> rgba;
    /// Rays that reached finestStep before the tolerance: the view ray, or one of the shadow
    /// rays of the integration it kept (those are also counted in unconvergedShadows).
    std::size_t unconverged = 0;
    std::size_t unconvergedShadows = 0;
    double finestStepUsed = 0.0;  ///< smallest step any ray, view or shadow, needed (world units)
    double at(int x, int y, int c) const { return rgba[(std::size_t(y) * width + x) * 4 + c]; }
};

/// Renders the emission-absorption integral of `scene`'s volumes (several volumes, overlapping or
/// not, add their media: extinction and emission sum; overlapping ones otherwise as their
/// ReferenceScene::Placed::blending says, each group of them composited front to back) seen
/// by `camera`. Rays run from the near
/// plane to the far plane, so a camera inside a volume sees what is in front of it.
/// With lights, each sample's emission is its TF colour lit as the node's settings say (Shading
/// null, lighting, lighting_threshold or lighting_surface; Illumination null, lambert, blinn_phong or
/// cook_torrance; ambient, specular, shininess, roughness), the normal from
/// ReferenceOptions::gradient (facing the viewer; the view direction where the gradient is
/// zero), and shadows as ReferenceScene::Placed::shadows says (unset: Shadowing null, none;
/// ray, exact): with exact shadows each light's term (not the ambient) is multiplied by the
/// transmittance exp(-∫ σ ds) from the sample towards the light, up to where that ray leaves the
/// sample's own volume box or reaches a point light. σ is that volume's extinction as the view
/// ray's (-ln(1 - α) / Δ0 of the trilinear value; infinite at α >= 1; NaN voxels and clipped
/// points empty), and is 0 where ReferenceScene::occluders (opaque triangles) cross the way to
/// the light; other volumes cast no shadow on it. Other choices throw std::invalid_argument.
/// The opaque geometry's colour (ReferenceOptions::geometryColour) is scaled, where volumes
/// shadow it (ReferenceScene::Placed::shadowsGeometry), by the product over those volumes of the
/// mean over the lights of the same transmittance from its surface point (the pixel's depth).
ReferenceImage renderReference(const ReferenceScene& scene, const ReferenceCamera& camera,
                               const ReferenceOptions& options = {});

}  // namespace volren
