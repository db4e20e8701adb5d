#pragma once
#include <volume_model/SceneInputs.h>

#include <osg/Vec3d>

#include <map>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace volren::app {

/// A usage error: bad or missing command-line argument (exit code 2).
struct UsageError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

/// Options of `volren render` (and `volren view`).
struct RenderOptions
{
    std::vector<std::string> inputs;        ///< scene, volume or model files; none = the default scene
    std::map<std::size_t, Placement> placements;  ///< --place N:SPEC, by input index (0-based here, 1-based on the line)
    std::string output;                     ///< image file (extension picks the format)
    int width = 512, height = 512;          ///< --size WxH
    bool sizeGiven = false;                 ///< --size was given (volren view opens larger without)
    std::optional<osg::Vec3d> eye, center, up;  ///< --eye/--center/--up
    std::optional<double> fov;              ///< --fov DEG (vertical)
    bool ortho = false;                     ///< --ortho fit|HEIGHT: parallel projection
    std::optional<double> orthoHeight;      ///< --ortho HEIGHT (world units, visible height); unset: fitted
    int turntable = 0;                      ///< --turntable N: N frames around the scene (0: one image)
    osg::Vec3d turntableAxis{0.0, 0.0, 1.0};  ///< --axis x|y|z|ax,ay,az
    std::optional<int> time;                ///< --time K: time point shown (from 0)
    bool everyTime = false;                 ///< --time all: one frame per time point
    std::string tfFile;                     ///< --tf FILE.tf | PRESETS.json[#NAME]
    bool tfKeepRange = false;               ///< --tf-keep-range: a ParaView preset keeps its own values
    osg::Vec3d background{0.0, 0.0, 0.0};   ///< --background r,g,b in [0,1]
    std::vector<std::pair<std::string, std::string>> settings;  ///< --set KEY=VALUE
    int frames = 1;                         ///< --frames N
    int samples = 1;                        ///< --samples N: multisampled framebuffer (MSAA)
    std::string screenshot;                 ///< view: --screenshot FILE after --frames N, then exit
    std::string statsFile;                  ///< --stats FILE.json
    std::string readerOptions;              ///< -O OPTION (repeatable): the volume reader's options
    /// --scale-bar / --no-scale-bar, --axes / --no-axes: the screen annotations (unset: off for
    /// render, on for view).
    std::optional<bool> scaleBar, axes;
};

/// Parses the arguments after `render`; throws UsageError naming the bad argument.
RenderOptions parseRenderOptions(const std::vector<std::string>& args, bool requireOutput);

/// Parses --place's "N:tx,ty,tz[:scale][:axis,angle]" into (N - 1, placement); throws UsageError.
std::pair<std::size_t, Placement> parsePlaceOption(const std::string& text);
/// Throws UsageError when --place names input `index` (0-based) of only `inputs`.
void checkPlacedInput(std::size_t index, std::size_t inputs);

/// Parses "x,y,z" (finite numbers); throws UsageError mentioning `what`.
osg::Vec3d parseVec3(const std::string& text, const std::string& what);

}  // namespace volren::app
