#pragma once
#include <volume_model/LoadProgress.h>

#include <osg/Node>

#include <string>

namespace volren {

/// Reads a scene file (.osgt, .osgb, .osgx or anything an OSG plugin reads) strictly: what
/// OSG's parser and the volren serializers only warn about (an unknown class or property, a
/// bad field value) fails the read too. Throws std::runtime_error "PATH: cannot read scene: WHY".
osg::ref_ptr<osg::Node> readSceneFile(const std::string& path);

/// The default scene (scenes/default.osgt, compiled into this library; its volume file is
/// found in shareDirectory()/data).
osg::ref_ptr<osg::Node> readDefaultScene();

/// INPUT as messages name it ("the default scene (scenes/default.osgt)" for "").
std::string inputName(const std::string& input);

}  // namespace volren
