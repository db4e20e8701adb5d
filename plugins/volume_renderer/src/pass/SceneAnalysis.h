#pragma once
#include <optional>
// Internal to the pass: what a VolumeScene's cull traversal finds below it.
#include <volume_renderer/CompositionPolicy.h>

#include <volume_model/VolumeNode.h>

#include <osg/Group>

#include <vector>

namespace volren {

/// One volume found below a VolumeScene, with what the scene offers it.
struct VolumeCandidate
{
    VolumeNode* node = nullptr;
    osg::Matrix matrix;        ///< node -> VolumeScene
    SceneOffer offer;          ///< lights, clip shapes and opaque geometry, in the node's coordinates
    osg::BoundingBoxd bound;   ///< its box in the VolumeScene's axes
    int lod = 0;               ///< mip level it is sampled from (levelOfDetail)
    bool coarseByteFiltering = false;  ///< the driver filters 8-bit textures to 8-bit results
    std::optional<osg::Matrixd> textureToClip;  ///< volume texture space -> the culling camera's clip space
    std::vector<LightInfo> sceneLights = {};  ///< the same lights in the VolumeScene's coordinates
    /// Volume texture space -> each light's opaque-geometry shadow map (BindContext::geometryShadowMatrices).
    std::vector<osg::Matrixd> geometryShadowMatrices = {};
    osg::ref_ptr<osg::Texture> geometryShadowMap = {};  ///< those maps, where its Shadowing reads them
};

/// The volumes (with a volume, a TF and voxels; a multi-channel node as the nodes of its visible
/// channels, which share its box and so one ray), lights, clip shapes and opaque geometry below
/// `scene`'s children that `mask` lets through; lights in eye coordinates are placed by the
/// camera's `modelView`. Warns once per call when more lights than a volume takes are found
/// and `lighting` is on.
std::vector<VolumeCandidate> analyseScene(osg::Group& scene, unsigned int mask, const osg::Matrix& modelView,
                                          bool lighting);

/// Volume texture space -> the VolumeNode's local coordinates.
osg::Matrixd textureToLocal(const Volume& volume);

}  // namespace volren
