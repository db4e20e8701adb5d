#pragma once
#include <volume_model/Volume.h>
#include <volume_model/VolumeNode.h>

#include <osg/Group>

namespace volren {

/// The scene a bare volume file gets: the volume centred at the origin with a transfer
/// function from its histogram, and one headlight (an osg::LightSource fixed to the camera).
osg::ref_ptr<osg::Group> makeDefaultScene(Volume* volume);

/// First VolumeNode found below `root` (depth first), or null.
VolumeNode* findFirstVolumeNode(osg::Node* root);

}  // namespace volren
