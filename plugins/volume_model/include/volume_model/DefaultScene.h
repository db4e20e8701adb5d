#pragma once
#include <volume_model/Volume.h>
#include <volume_model/VolumeNode.h>

#include <osg/Group>
#include <osg/LightSource>

#include <vector>

namespace volren {

/// A new volume pass (a `volren::VolumeScene`, made through OSG's wrapper registry so that
/// the model does not link GL); a plain osg::Group, with a warning, when the serializer plugin
/// cannot be found.
osg::ref_ptr<osg::Group> makeSceneRoot();

/// The scene a bare volume file gets, under makeSceneRoot(): the volume centred at the origin
/// with a transfer function from its histogram, and one headlight (an osg::LightSource fixed
/// to the camera). Any OSG viewer renders it.
osg::ref_ptr<osg::Group> makeDefaultScene(Volume* volume);
/// The default scene's light: directional along the view, fixed to the camera (light 0).
osg::ref_ptr<osg::LightSource> makeHeadlight();
/// A VolumeNode showing `volume` (named by its file) with a transfer function from its histogram;
/// a volume of several channels (held whole) shows them all, each in its default colour over its
/// percentile window (defaultChannelDisplays), unshaded (Shading null: fluorescence emits).
osg::ref_ptr<VolumeNode> makeDefaultVolumeNode(Volume* volume);

/// First VolumeNode found below `root` (depth first), or null.
VolumeNode* findFirstVolumeNode(osg::Node* root);
/// Every VolumeNode below `root`, in traversal order (all children, whatever their masks).
std::vector<VolumeNode*> findVolumeNodes(osg::Node& root);

}  // namespace volren
