#pragma once
// Results of `volren bench` and how they are written: Markdown, CSV, JSON, and a plot of error
// against frame time with the Pareto front marked (gnuplot).
#include <volume_reference/ReferenceRenderer.h>
#include <volume_renderer/VolumeScene.h>

#include <osg/Image>

#include <string>
#include <utility>
#include <vector>

namespace volren::app {

/// An image against its reference, over the RGBA channels.
struct ImageError
{
    double rmse = -1.0;     ///< root mean square error
    double maxAbs = -1.0;   ///< largest absolute error
    double psnr = -1.0;     ///< 20 log10(1 / rmse) dB (peak 1)
};

/// `image` (RGBA float, row 0 at the bottom) against `truth` of the same size.
ImageError imageError(const osg::Image& image, const ReferenceImage& truth);

/// One configuration on one dataset at one size.
struct BenchRow
{
    std::string dataset, config, truth;  ///< truth: which reference (the lighting model drawn)
    std::string renderer = "volren";     ///< or the peer ("VTK ...")
    int width = 0, height = 0;
    double frameMs = -1.0, gpuMs = -1.0, cpuMs = -1.0;  ///< medians
    double frameNoiseMs = 0.0;  ///< median absolute deviation of the frame times
    double textureMb = -1.0;    ///< GL texture storage volren allocated
    double gpuMemoryMb = -1.0;  ///< drop of the driver's free video memory (NVIDIA), -1 unknown
    /// Shadowed rows: median frame time while the light moves every frame (-1: not measured).
    double lightMoveMs = -1.0;
    /// Light volumes: time of their last build, and their bytes per voxel of the volumes (-1: none).
    double rebuildMs = -1.0, auxBytesPerVoxel = -1.0;
    ImageError error;
    std::vector<std::string> keys;  ///< composition keys drawn
    bool pareto = false;            ///< on the speed/accuracy Pareto front of its dataset and size
    /// Better than the default on one axis beyond the run's noise, not worse on the other.
    bool beatsDefault = false;
    bool beatenByDefault = false;   ///< the default beats it by the same rule
};

struct BenchReport
{
    std::string context;     ///< the GL context
    std::string timingNote;  ///< what the times mean
    std::vector<BenchRow> rows;
};

/// Marks the Pareto front (volren rows of each dataset and size: no other row is both at least
/// as fast and at least as accurate, and better in one) and writes DIR/bench.md, .csv, .json and
/// .png (the plot needs gnuplot; without it DIR/bench.gp is left for later and a note printed).
void writeReport(BenchReport& report, const std::string& directory);

/// Renders `scene` as seen by `camera` with VTK's GPU ray caster (python3-vtk9 under xvfb-run):
/// same volume file, transfer function, view, size, sample distance and headlight. Returns its
/// row (times) and its image; throws std::runtime_error when VTK or Xvfb is missing.
std::pair<BenchRow, osg::ref_ptr<osg::Image>> runVtkPeer(const VolumeScene& scene, const ReferenceCamera& camera,
                                                         int frames, const std::string& directory);

}  // namespace volren::app
