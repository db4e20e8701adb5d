#pragma once
#include <volume_model/ClipNode.h>
#include <volume_model/VolumeNode.h>

#include <osg/Geometry>
#include <osg/Matrixd>
#include <osg/Node>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace volren {

/// What the reference renderer sees of a scene graph: each VolumeNode and each clip shape with
/// its local-to-world matrix (the nodes are referenced, not copied).
struct ReferenceScene
{
    /// How the light reaching a lit sample is modelled: every light unoccluded, or each light's
    /// term times the exact transmittance from the sample to the light through the sample's own
    /// volume (what every GPU Shadowing method approximates).
    enum class Shadows { None, Exact };

    /// How volumes whose boxes overlap combine along a ray (the renderer's multi-volume set
    /// traversal: its ImplementationTraits::combines): their media add (the emission-absorption
    /// integral of the summed medium: optical depths add, emissions mix), their own
    /// emission-absorption images add, or their classified maxima (MIP, unlit, premultiplied)
    /// add. Added colours are clamped to 1; the coverage of added images is 1 - prod(1 - alpha).
    enum class Blending { Media, Images, Maxima };

    /// The models of light the reference implements, by slot (Shading, Illumination, Shadowing,
    /// Weighting): what an implementation's declared ReferenceModel may name. The reference
    /// selects each volume's models by the declarations of the implementations it is drawn with.
    static const std::map<std::string, std::vector<std::string>>& models();
    static constexpr const char* exactShadows = "exact shadows";  ///< Shadowing: Shadows::Exact
    /// Shadowing: Shadows::Exact, and the ambient term scaled by its occlusion.
    static constexpr const char* exactShadowsAndOcclusion = "exact shadows and occlusion";

    struct Placed
    {
        osg::ref_ptr<const osg::Node> node;
        osg::Matrixd localToWorld;
        /// Volumes: the implementations the renderer chose for it (slot -> name; the lighting
        /// models are those the Shading, Illumination, Shadowing and Weighting chosen declare,
        /// ReferenceModelCatalog). Empty: the node's own settings, an unset slot being null
        /// (referenceSetup() fills it from the CompositionPolicy).
        std::map<std::string, std::string> choice = {};
        /// Volumes: their shadow model. Unset: the declared model of the Shadowing choice (an
        /// implementation that only approximates its model makes renderReference throw, so that
        /// a caller says what it measures). referenceSetup() sets it from the declared model of
        /// the renderer's choice, so that an approximation of exact shadows is measured against them.
        std::optional<Shadows> shadows = {};
        /// Volumes: their ambient term is scaled by its occlusion (the cosine-weighted hemisphere
        /// integral of the transmittance over the settings' coneStart..aoDistance). referenceSetup()
        /// sets it from the declared model of the renderer's Shadowing choice.
        bool occlusion = false;
        /// Volumes: they shadow the opaque geometry: each geometry pixel's colour is scaled by
        /// the mean over the lights of the transmittance from its surface point to each light
        /// through this volume (several such volumes: the product of theirs). referenceSetup()
        /// sets it where an implementation chosen needs data that darkens the geometry (AuxKind).
        bool shadowsGeometry = false;
        /// Volumes: how it combines with the volumes its box overlaps (transitively: a group, as
        /// the renderer's ray groups); a group takes its first volume's. Groups that do not
        /// overlap are composited front to back along each ray, as the renderer draws them.
        /// referenceSetup() sets it from the renderer's set traversal for the volume.
        Blending blending = Blending::Media;
    };
    /// VolumeNodes with a volume and a transfer function (a multi-channel node as the nodes of
    /// its visible channels, VolumeNode::drawnNodes, as the renderer draws it)
    std::vector<Placed> volumes;
    std::vector<Placed> clips;    ///< ClipNodes
    /// osg::LightSources with a light; ABSOLUTE_RF ones keep eye coordinates (localToWorld is
    /// then the identity and the camera places them).
    std::vector<Placed> lights;
    /// The opaque geometry's triangles in world coordinates (drawables that are not drawn after
    /// the opaque bin, outside volume and clip nodes), with a k-d tree; null when there are none.
    osg::ref_ptr<osg::Geometry> occluders;

    /// Whether the segment from world point `from` to `to` crosses an opaque triangle.
    bool occluded(const osg::Vec3d& from, const osg::Vec3d& to) const;

    /// Collects the volumes, clip shapes, lights and opaque triangles below `root` (all children,
    /// whatever their masks).
    static ReferenceScene collect(const osg::Node& root);
};

}  // namespace volren
