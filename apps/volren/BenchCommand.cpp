// `volren bench`: speed against accuracy. Every configuration of the matrix is rendered on each
// dataset at each size; its frame time is the median over frames after warm-up, its error is
// measured against the CPU reference of the same view (one reference per distinct picture: the
// lighting model is part of what is drawn, the rest are approximations of it). Lit references
// take their normals from central differences by default (--normals central), the convention
// every gradient option approximates; --normals exact measures against the exact gradient of
// the trilinear field instead (all lit configurations then share a ~0.016 RMSE floor on ch2).
#include "BenchReport.h"
#include "CommandLine.h"
#include "Commands.h"
#include "SceneSetup.h"

#include <volume_reference/ReferenceSetup.h>
#include <volume_renderer/OffscreenRenderer.h>
#include <volume_renderer/SceneSettings.h>

#include <volume_model/DefaultScene.h>
#include <volume_model/Requantise.h>

#include <osg/GLExtensions>
#include <osgDB/FileNameUtils>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

#ifndef GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX
#define GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX 0x9049
#endif

namespace volren::app {

namespace {

/// One point of the matrix: settings on top of the scene's own, and the texture precision.
struct BenchConfig
{
    std::string name;                                           ///< e.g. "samplerate=4"
    std::vector<std::pair<std::string, std::string>> settings;  ///< --set KEY=VALUE
    std::string precision = "native";                           ///< native, 8bit, 16bit, float
};

/// The default matrix: the scene's defaults, then one option changed at a time.
std::vector<BenchConfig> defaultMatrix()
{
    std::vector<BenchConfig> m{{"default", {}, "native"}};
    auto add = [&](const std::string& key, const std::vector<std::string>& values) {
        for (const std::string& v : values) m.push_back({key + "=" + v, {{key, v}}, "native"});
    };
    add("samplerate", {"0.5", "1", "4", "8"});
    add("reconstruction", {"nearest", "tricubic"});
    add("gradient", {"forward", "central9"});
    add("illumination", {"lambert", "cook_torrance"});
    add("lighting", {"off"});
    add("earlyTermination", {"0.99", "1"});
    add("jitter", {"null", "texture"});
    add("classification", {"premultiplied"});
    for (const char* p : {"8bit", "16bit", "float"}) m.push_back({std::string("precision=") + p, {}, p});
    return m;
}

/// What a reference draws, so configurations that draw the same picture share one: each
/// volume's lighting model as the policy chose it ("lit:blinn_phong", "unlit").
std::string lightingModel(const ReferenceScene& scene, bool lighting)
{
    std::string key;
    for (const auto& placed : scene.volumes) {
        const auto shading = placed.choice.find("Shading");
        const bool lit = lighting && !scene.lights.empty() && shading != placed.choice.end() && shading->second != "null";
        key += (key.empty() ? "" : "+") + (lit ? "lit:" + placed.choice.at("Illumination") : std::string("unlit"));
    }
    return key;
}

double median(std::vector<double> v)
{
    if (v.empty()) return -1.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Free GPU memory in MiB where the driver tells (NVIDIA's GL_NVX_gpu_memory_info), else -1.
double freeGpuMemoryMb(osg::State& state)
{
    if (!osg::isGLExtensionSupported(state.getContextID(), "GL_NVX_gpu_memory_info")) return -1.0;
    GLint kb = 0;
    glGetIntegerv(GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, &kb);
    return kb / 1024.0;
}

struct BenchOptions
{
    std::vector<std::string> inputs;
    std::vector<std::pair<int, int>> sizes{{256, 256}};
    int frames = 5;
    std::string out = "bench";
    std::vector<std::string> only;  ///< config names to run (empty: all)
    double tolerance = 1e-3;
    bool vtk = false;
    ReferenceOptions::Gradient normals = ReferenceOptions::Gradient::CentralDifferences;
};

BenchOptions parseBenchOptions(const std::vector<std::string>& args)
{
    BenchOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + ": missing value");
            return args[++i];
        };
        if (a == "--size") {
            o.sizes.clear();
            std::stringstream list(value());
            for (std::string item; std::getline(list, item, ',');) {
                int w = 0, h = 0;
                char x = 0;
                std::istringstream in(item);
                if (!(in >> w >> x >> h) || x != 'x' || w < 1 || h < 1 || w > 8192 || h > 8192)
                    throw UsageError("--size: expected WxH[,WxH...] with 1..8192, got '" + item + "'");
                o.sizes.emplace_back(w, h);
            }
        } else if (a == "--frames") {
            o.frames = std::atoi(value().c_str());
            if (o.frames < 1 || o.frames > 1000) throw UsageError("--frames: must be 1..1000");
        } else if (a == "--out") {
            o.out = value();
        } else if (a == "--configs") {
            std::stringstream list(value());
            for (std::string item; std::getline(list, item, ';');) o.only.push_back(item);
        } else if (a == "--tolerance") {
            o.tolerance = std::atof(value().c_str());
            if (!(o.tolerance > 0.0 && o.tolerance < 1.0)) throw UsageError("--tolerance: must be in (0, 1)");
        } else if (a == "--vtk") {
            o.vtk = true;
        } else if (a == "--normals") {
            const std::string& v = value();
            if (v == "exact") o.normals = ReferenceOptions::Gradient::Exact;
            else if (v == "central") o.normals = ReferenceOptions::Gradient::CentralDifferences;
            else throw UsageError("--normals: exact or central, got '" + v + "'");
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option '" + a + "'");
        } else {
            o.inputs.push_back(a);
        }
    }
    if (o.inputs.empty()) o.inputs.push_back("");  // the default scene
    return o;
}

}  // namespace

int benchCommand(const std::vector<std::string>& args)
{
    const BenchOptions options = parseBenchOptions(args);
    std::vector<BenchConfig> matrix = defaultMatrix();
    if (!options.only.empty()) {
        std::vector<BenchConfig> chosen;
        for (const std::string& name : options.only) {
            auto it = std::find_if(matrix.begin(), matrix.end(), [&](const BenchConfig& c) { return c.name == name; });
            if (it == matrix.end()) throw UsageError("--configs: no configuration '" + name + "'");
            chosen.push_back(*it);
        }
        matrix = chosen;
    }
    BenchReport report;
    report.timingNote = "frame_ms: median draw time (first draw call to glFinish) over the frames after 2 warm-up "
                        "frames; gpu_ms: GL_TIME_ELAPSED (on Mesa llvmpipe it misses rasterisation); cpu_ms: the "
                        "whole frame";
    for (const std::string& input : options.inputs) {
        for (const auto& [width, height] : options.sizes) {
            RenderOptions ro;
            ro.input = input;
            ro.width = width;
            ro.height = height;
            osg::ref_ptr<VolumeScene> scene = loadScene(ro);
            const std::string dataset = input.empty() ? "default.osgt (ch2.nii.gz)" : osgDB::getSimpleFileName(input);
            const std::vector<VolumeNode*> nodes = findVolumeNodes(*scene);
            if (nodes.empty()) throw std::runtime_error(dataset + ": the scene shows no volume");
            std::vector<std::pair<RenderSettings, osg::ref_ptr<Volume>>> original;
            for (VolumeNode* n : nodes) original.emplace_back(n->settings, n->getVolume());
            const PassSettings originalPass = scene->pass;

            OffscreenRenderer renderer(width, height);
            report.context = renderer.contextDescription();
            renderer.setScene(scene.get());
            setUpCamera(*renderer.camera(), *scene, ro, double(width) / height);
            ReferenceCamera camera;
            camera.view = renderer.camera()->getViewMatrix();
            camera.projection = renderer.camera()->getProjectionMatrix();
            camera.width = width;
            camera.height = height;

            std::map<std::string, ReferenceImage> truths;  // by what is drawn (the lighting model)
            for (const BenchConfig& config : matrix) {
                // The scene as the configuration draws it.
                scene->pass = originalPass;
                for (std::size_t k = 0; k < nodes.size(); ++k) {
                    nodes[k]->settings = original[k].first;
                    nodes[k]->setVolume(original[k].second.get());
                }
                for (const auto& [key, value] : config.settings) {
                    try {
                        applySetting(*scene, key, value);
                    } catch (const SettingError& e) {
                        throw UsageError(config.name + ": " + e.what());
                    }
                }
                // Its truth: the reference of the same scene at full precision, as volren reference makes it.
                const std::string truthKey = lightingModel(referenceScene(*scene), scene->pass.lighting);
                if (!truths.count(truthKey)) {
                    ReferenceOptions ref;
                    ref.tolerance = options.tolerance;
                    ref.gradient = options.normals;
                    const auto start = std::chrono::steady_clock::now();
                    const ReferenceSetup setup = referenceSetup(*scene, camera, ref);
                    truths[truthKey] = renderReference(setup.scene, camera, setup.options);
                    std::cerr << "volren bench: reference '" << truthKey << "' of " << dataset << " at " << width << "x"
                              << height << " in "
                              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s"
                              << std::endl;
                }
                if (config.precision != "native")
                    for (VolumeNode* n : nodes) {
                        const VoxelType type = config.precision == "8bit"    ? VoxelType::UInt8
                                               : config.precision == "16bit" ? VoxelType::UInt16
                                                                             : VoxelType::Float32;
                        n->setVolume(requantise(*n->getVolume(), type).get());
                    }

                renderer.setScene(scene.get());
                const double freeBefore = freeGpuMemoryMb(*renderer.state());
                std::vector<double> draw, gpu, cpu;
                for (int f = 0; f < options.frames + 2; ++f) {
                    const FrameTiming t = renderer.renderFrame();
                    if (!t.glErrors.empty()) throw std::runtime_error(config.name + ": GL error: " + t.glErrors.front());
                    if (f < 2) continue;  // warm-up: programs compiled, textures uploaded
                    draw.push_back(t.drawMs);
                    gpu.push_back(t.gpuMs);
                    cpu.push_back(t.cpuMs);
                }
                const double freeAfter = freeGpuMemoryMb(*renderer.state());

                BenchRow row;
                row.dataset = dataset;
                row.width = width;
                row.height = height;
                row.config = config.name;
                row.truth = truthKey;
                row.frameMs = median(draw);
                row.gpuMs = median(gpu);
                row.cpuMs = median(cpu);
                row.textureMb = double(renderer.volumeScene()->textureBytes()) / (1024.0 * 1024.0);
                row.gpuMemoryMb = freeBefore >= 0.0 && freeAfter >= 0.0 ? freeBefore - freeAfter : -1.0;
                row.error = imageError(*renderer.image(), truths[truthKey]);
                row.keys = renderer.volumeScene()->compositionKeys();
                std::cerr << "volren bench: " << config.name << ": " << row.frameMs << " ms, RMSE " << row.error.rmse
                          << std::endl;
                report.rows.push_back(row);
            }
            if (options.vtk) {
                for (std::size_t k = 0; k < nodes.size(); ++k) {
                    nodes[k]->settings = original[k].first;
                    nodes[k]->setVolume(original[k].second.get());
                }
                scene->pass = originalPass;
                const auto peer = runVtkPeer(*scene, camera, options.frames, options.out);
                BenchRow row = peer.first;
                row.dataset = dataset;
                const std::string truthKey = lightingModel(referenceScene(*scene), scene->pass.lighting);
                row.truth = truthKey;
                if (truths.count(truthKey)) row.error = imageError(*peer.second, truths[truthKey]);
                report.rows.push_back(row);
            }
        }
    }
    writeReport(report, options.out);
    std::cout << "volren bench: wrote " << options.out << "/bench.{md,csv,json,png}" << std::endl;
    return 0;
}

}  // namespace volren::app
