#pragma once
#include <osg/Vec3d>
#include <osgDB/Options>

#include <optional>

namespace volren::stack {

/// The `spacing=x,y,z` token of `options`' option string, if there is one. Throws
/// std::runtime_error when the token is present but not three positive finite numbers.
std::optional<osg::Vec3d> spacingOption(const osgDB::Options* options);

}  // namespace volren::stack
