#pragma once
#include <volume_model/Volume.h>

#include <osg/Group>
#include <osg/Matrixd>
#include <osg/Vec3d>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace volren {

/// Where one input goes in a combined scene: scaled, then rotated, then moved (world units).
struct Placement
{
    osg::Vec3d translation{0.0, 0.0, 0.0};  ///< tx,ty,tz
    osg::Vec3d scale{1.0, 1.0, 1.0};        ///< sx,sy,sz (or one factor for all three)
    osg::Vec3d axis{0.0, 0.0, 1.0};         ///< rotation axis (x, y, z or a vector)
    double angleDegrees = 0.0;              ///< rotation about `axis`, right-handed

    /// The placement as a matrix (OSG's row-vector convention: scale * rotate * translate).
    osg::Matrixd matrix() const;
};

/// Parses "tx,ty,tz[:s|:sx,sy,sz][:AXIS,ANGLE]" where AXIS is x, y, z or ax,ay,az and ANGLE is
/// in degrees; throws std::invalid_argument saying what is wrong.
Placement parsePlacement(const std::string& text);

/// What an input file holds.
enum class InputKind
{
    Scene,   ///< an OSG scene file (.osgt, .osgb, .osgx, .osg, .ive): its nodes as they are
    Volume,  ///< a volume file (isVolumeFile): a VolumeNode with a TF from its histogram
    Model,   ///< any other file an OSG plugin reads (.obj, .ply, .stl, .iv, ...): polygons
};

/// The kind of `path` by its name (a folder is a volume: slices or a zarr image).
InputKind inputKind(const std::string& path);

/// One input of a command line: a file and where it goes.
struct SceneInput
{
    std::string path;                    ///< scene, volume or model file
    std::optional<Placement> placement;  ///< none: where the file puts it
};

/// Reads a volume file (the CLI passes one that shows a progress bar and applies -O options).
using VolumeFileReader = std::function<osg::ref_ptr<Volume>(const std::string& path)>;

/// Reads `inputs` and combines them under one scene root (makeSceneRoot; the first scene
/// file's own VolumeScene, so its pass settings hold). A scene file adds its root's children,
/// a volume file a VolumeNode centred at the origin with a TF from its histogram, a model an
/// osg::ProxyNode naming the file (so a written scene refers to it) holding what OSG read.
/// Each placed input goes under an osg::MatrixTransform. When no input is a scene file and none
/// brings a light, the scene gets the default scene's headlight. Throws std::runtime_error naming the file.
osg::ref_ptr<osg::Group> readSceneInputs(const std::vector<SceneInput>& inputs, const VolumeFileReader& readVolume);

/// Makes every model file a ProxyNode names relative to `folder` (where a scene file is being
/// written), so the written scene finds them next to it wherever the pair is moved.
void makeModelPathsRelative(osg::Node& scene, const std::string& folder);

}  // namespace volren
