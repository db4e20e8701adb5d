#include "Commands.h"
#include "ImageWriter.h"
#include "SceneSetup.h"
#include "Sequence.h"

#include <volume_renderer/OffscreenRenderer.h>

#include <nlohmann/json.hpp>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>

namespace volren::app {

namespace {

double median(std::vector<double> v)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int renderCommand(const std::vector<std::string>& args, bool defaultRun)
{
    RenderOptions options = parseRenderOptions(args, !defaultRun);
    if (defaultRun) options.output = "volren.png";
    const std::string input = inputName(options);

    osg::ref_ptr<VolumeScene> scene = loadScene(options);
    addAnnotations(*scene, options, false);
    OffscreenRenderer renderer(options.width, options.height, options.samples);
    renderer.setScene(scene.get());
    renderer.setBackground(osg::Vec3(options.background));
    setUpCamera(*renderer.camera(), *scene, options, double(options.width) / options.height);

    std::vector<FrameTiming> frames;
    std::vector<FrameTiming> streamed;
    const auto streamStart = std::chrono::steady_clock::now();
    // Streaming bricks (--set streamBricks=on): frames go on until every brick they plan is in
    // its pool, so the image written is the converged one, as without streaming.
    auto converge = [&] {
        if (VolumeScene* volumes = renderer.volumeScene(); volumes && volumes->pass.streamBricks)
            while (volumes->pendingBricks() > 0) {
                volumes->waitForBricks(1.0);
                streamed.push_back(renderer.renderFrame());
            }
    };
    for (int i = 0; i < options.frames; ++i) frames.push_back(renderer.renderFrame());
    // A volume the pass could not draw (its composition or data refused) fails the command: an
    // image without it would be a silent wrong picture.
    for (const FrameTiming& f : frames)
        if (!f.drawErrors.empty()) throw std::runtime_error(f.drawErrors.front());
    converge();
    const double streamMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - streamStart).count();
    WrittenFrames written;
    if (isSequence(options)) {
        written = renderSequence(renderer, *scene, options, converge, frames);
    } else {
        writeImage(*renderer.image(), options.output);
        written.path = osgDB::getRealPath(options.output);
    }

    if (!options.statsFile.empty()) {
        nlohmann::json stats;
        stats["input"] = input;
        stats["output"] = options.output;
        stats["width"] = options.width;
        stats["height"] = options.height;
        stats["context"] = renderer.contextDescription();
        stats["timing_note"] =
            "cpu_ms: whole frame; draw_ms: first draw call to glFinish; gpu_ms: GL_TIME_ELAPSED query, "
            "which on Mesa llvmpipe does not include rasterisation (use draw_ms there); null where the query "
            "returned a time longer than the whole frame's, which cannot be true";
        stats["composition_keys"] = renderer.volumeScene()->compositionKeys();
        nlohmann::json bricks = nlohmann::json::array();  // bricked volumes: what their pools hold
        for (const BrickStatistics& b : renderer.volumeScene()->brickStatistics())
            bricks.push_back({{"volume", b.volume},
                              {"level_sampled", b.levelSampled},
                              {"bricks_resident", b.resident},
                              {"bricks_constant", b.constant},
                              {"bricks_hidden", b.hidden},
                              {"bricks_missing", b.missing},
                              {"bricks_pending", b.pending},
                              {"bricks_loaded", b.loaded},
                              {"bricks_uploaded", b.uploaded},
                              {"bricks_evicted", b.evicted},
                              {"pool_bytes", b.poolBytes},
                              {"budget_bytes", b.budgetBytes},
                              {"source_ram_bytes", b.sourceBytes}});
        stats["bricked_volumes"] = bricks;
        nlohmann::json built = nlohmann::json::array();  // shadowing=light_volume, cone, cone_ao
        for (const BuiltVolumeStatistics& l : renderer.volumeScene()->builtVolumeStatistics())
            built.push_back({{"volume", l.node},
                                    {"kind", l.kind},
                                    {"dims", {l.dims.x(), l.dims.y(), l.dims.z()}},
                                    {"channels", l.channels},
                                    {"bytes", l.bytes},
                                    {"bytes_per_voxel", l.volumeVoxels ? double(l.bytes) / double(l.volumeVoxels) : 0.0},
                                    {"builds", l.builds},
                                    {"last_build_ms", l.lastBuildSeconds * 1e3}});
        stats["built_volumes"] = built;
        stats["geometry_shadow_map_draws"] = renderer.volumeScene()->geometryShadowMapDraws();
        stats["streamed_frames"] = streamed.size();  // frames after --frames until the bricks converged
        stats["streamed_ms"] = streamMs;
        std::vector<double> cpu, draw, gpu;
        nlohmann::json perFrame = nlohmann::json::array();
        for (const FrameTiming& f : frames) {
            perFrame.push_back({{"cpu_ms", f.cpuMs},
                                {"draw_ms", f.drawMs},
                                {"gpu_ms", f.gpuMs >= 0 ? nlohmann::json(f.gpuMs) : nlohmann::json()}});
            cpu.push_back(f.cpuMs);
            draw.push_back(f.drawMs);
            if (f.gpuMs >= 0) gpu.push_back(f.gpuMs);
        }
        stats["frames"] = perFrame;
        // The first frame pays for shader compilation and uploads; medians skip it when there are more.
        auto steady = [](const std::vector<double>& v) {
            return v.size() > 1 ? std::vector<double>(v.begin() + 1, v.end()) : v;
        };
        stats["cpu_ms_median"] = median(steady(cpu));
        stats["draw_ms_median"] = median(steady(draw));
        stats["gpu_ms_median"] = gpu.empty() ? nlohmann::json() : nlohmann::json(median(steady(gpu)));
        std::ofstream out(options.statsFile);
        out << stats.dump(2) << "\n";
        if (!out) throw std::runtime_error(options.statsFile + ": cannot write statistics");
    }

    std::cout << "volren: wrote " << written.path << " (" << options.width << "x" << options.height << ", "
              << (isSequence(options) ? std::to_string(written.frames) + " frames, " : std::string()) << input << ")"
              << std::endl;
    return 0;
}

}  // namespace volren::app
