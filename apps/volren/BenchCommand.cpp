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
#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/Slots.h>

#include <volume_model/DefaultScene.h>
#include <volume_model/ReferenceModel.h>
#include <volume_model/Requantise.h>
#include <volume_model/SpatialWeighting.h>
#include <volume_model/VolumeNode.h>

#include <osg/GLExtensions>
#include <osg/LightSource>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

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

/// The default matrix: the scene's defaults, then one option changed at a time: the settings
/// every volume has, then the rows each implementation declares (ShaderFunction::benchRows).
std::vector<BenchConfig> defaultMatrix()
{
    std::vector<BenchConfig> m{{"default", {}, "native"}};
    auto add = [&](const std::string& key, const std::vector<std::string>& values) {
        for (const std::string& v : values) m.push_back({key + "=" + v, {{key, v}}, "native"});
    };
    add("samplerate", {"0.5", "1", "4", "8"});
    add("lighting", {"off"});
    add("earlyTermination", {"0.95", "0.99", "1"});  // 0.95: the default before it was error-bounded
    add("macrocellSize", {"4", "16"});
    add("lod", {"1", "2"});
    add("lodByDistance", {"on"});
    add("texturePrecision", {"native", "16bit"});
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    for (const SlotInfo& slot : slots()) {
        const std::string key = RenderSettings::keyForSlot(slot.name);  // the setting that chooses it
        for (const std::string& name : registry.names(slot.name))
            for (const auto& row : registry.find(slot.name, name)->benchRows) {
                BenchConfig config{key + "=" + name, {{key, name}}, "native"};
                for (const auto& [k, v] : row) {
                    config.name += "+" + k + "=" + v;
                    config.settings.emplace_back(k, v);
                }
                m.push_back(config);
            }
    }
    for (const char* p : {"8bit", "16bit", "float"}) m.push_back({std::string("precision=") + p, {}, p});
    return m;
}

/// The model the reference computes for the implementation of `slot` the renderer chose for
/// `placed` (its declared ReferenceModel), "" where none is chosen.
std::string modelOf(const ReferenceScene::Placed& placed, const std::string& slot)
{
    const auto chosen = placed.choice.find(slot);
    if (chosen == placed.choice.end()) return {};
    const ReferenceModel* declared = ReferenceModelCatalog::instance().find(slot, chosen->second);
    return declared ? declared->model : "undeclared " + chosen->second;
}

/// What a reference draws, so configurations that draw the same picture share one: each
/// volume's lighting model as the policy chose it and its implementations declare
/// ("lit:diffuse + blinn-phong highlight", "lit:lambert diffuse/lit on surfaces", "unlit"),
/// its spatial weighting ("unlit weightZ=0:0,0.1:1") and how it combines with overlapping ones
/// ("unlit added", "unlit maximum").
std::string lightingModel(const ReferenceScene& scene, bool lighting)
{
    std::string key;
    for (const auto& placed : scene.volumes) {
        const std::string shading = modelOf(placed, "Shading");
        const bool lit = lighting && !scene.lights.empty() && !shading.empty() && shading != "unlit";
        std::string model = lit ? "lit:" + modelOf(placed, "Illumination") : std::string("unlit");
        if (lit && shading != "lit") model += "/" + shading;  // another lit picture
        // What its Shadowing approximates (referenceScene fills it from the declared model).
        if (lit && placed.shadows == ReferenceScene::Shadows::Exact) model += "+shadows";
        if (lit && placed.occlusion) model += "+occlusion";
        if (lit && placed.shadowsGeometry && scene.occluders) model += "+shadowed geometry";
        // Its spatial weighting where the renderer applies it (another picture per curve).
        if (modelOf(placed, "Weighting") == "axis curves")
            if (const auto* node = dynamic_cast<const VolumeNode*>(placed.node.get())) {
                const SpatialWeighting curves = spatialWeighting(node->settings);
                for (std::size_t axis = 0; axis < 3; ++axis)
                    if (!curves.axes[axis].identity())
                        model += std::string(" weight") + "XYZ"[axis] + "=" + curves.axes[axis].text();
            }
        // How it combines with the volumes it overlaps (the same media, other pictures).
        if (placed.blending == ReferenceScene::Blending::Images) model += " added";
        if (placed.blending == ReferenceScene::Blending::Maxima) model += " maximum";
        key += (key.empty() ? "" : "+") + model;
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
    bool checkFront = false;  ///< fail when a row beats the default (BenchFront.h)
    bool listConfigs = false;  ///< print the configurations' names and settings, run none
    std::string tf;           ///< --tf FILE: every volume's transfer function (as volren render's)
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
        } else if (a == "--check-front") {
            o.checkFront = true;
        } else if (a == "--list-configs") {
            o.listConfigs = true;
        } else if (a == "--vtk") {
            o.vtk = true;
        } else if (a == "--tf") {
            o.tf = value();
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

/// The files of one bench dataset: "" none (the default scene), "ct.nii.gz+tool.obj" several
/// combined into one scene (unless a file of that very name exists).
std::vector<std::string> datasetFiles(const std::string& dataset)
{
    if (dataset.empty()) return {};
    if (osgDB::fileExists(dataset)) return {dataset};
    std::vector<std::string> files;
    std::stringstream list(dataset);
    for (std::string file; std::getline(list, file, '+');)
        if (!file.empty()) files.push_back(file);
    return files;
}

/// One dataset at one size: its scene, the renderer, the camera, and the truths computed so far.
class BenchRun
{
public:
    BenchRun(const std::string& input, int width, int height, const BenchOptions& options)
        : _options(options), _width(width), _height(height), _renderer(width, height)
    {
        RenderOptions ro;
        ro.inputs = datasetFiles(input);
        ro.width = width;
        ro.height = height;
        ro.tfFile = options.tf;
        _scene = loadScene(ro);
        _dataset = input.empty() ? "default.osgt (ch2.nii.gz)" : osgDB::getSimpleFileName(input);
        _nodes = findVolumeNodes(*_scene);
        if (_nodes.empty()) throw std::runtime_error(_dataset + ": the scene shows no volume");
        for (VolumeNode* n : _nodes) _original.emplace_back(n->settings, n->getVolume());
        _originalPass = _scene->pass;
        _renderer.setScene(_scene.get());
        setUpCamera(*_renderer.camera(), *_scene, ro, double(width) / height);
        _camera.view = _renderer.camera()->getViewMatrix();
        _camera.projection = _renderer.camera()->getProjectionMatrix();
        _camera.width = width;
        _camera.height = height;
    }

    std::string context() const { return _renderer.contextDescription(); }

    /// The row of `config`: its frame time and its error against the truth of what it draws.
    BenchRow run(const BenchConfig& config)
    {
        restore();
        for (const auto& [key, value] : config.settings) {
            try {
                applySetting(*_scene, key, value);
            } catch (const SettingError& e) {
                throw UsageError(config.name + ": " + e.what());
            }
        }
        const std::string truth = truthKey();
        if (config.precision != "native")
            for (VolumeNode* n : _nodes) n->setVolume(requantise(*n->getVolume(), precisionType(config.precision)).get());
        BenchRow row = timeFrames(config.name);
        row.truth = truth;
        row.error = imageError(*_renderer.image(), _truths.at(truth));
        measureLightMoves(row);  // after the error: it renders with the lights turned
        std::cerr << "volren bench: " << config.name << ": " << row.frameMs << " ms, RMSE " << row.error.rmse << std::endl;
        return row;
    }

    /// The row of VTK's GPU ray caster on the scene's own settings.
    BenchRow runVtk()
    {
        restore();
        const auto peer = runVtkPeer(*_scene, _camera, _options.frames, _options.out);
        BenchRow row = peer.first;
        row.dataset = _dataset;
        row.truth = truthKey();
        row.error = imageError(*peer.second, _truths.at(row.truth));
        return row;
    }

private:
    static VoxelType precisionType(const std::string& precision)
    {
        return precision == "8bit" ? VoxelType::UInt8 : precision == "16bit" ? VoxelType::UInt16 : VoxelType::Float32;
    }

    /// The scene's own settings, pass settings and volumes.
    void restore()
    {
        _scene->pass = _originalPass;
        for (std::size_t k = 0; k < _nodes.size(); ++k) {
            _nodes[k]->settings = _original[k].first;
            _nodes[k]->setVolume(_original[k].second.get());
        }
    }

    /// The truth of what the scene draws now (made on first use): the reference at full
    /// precision, as `volren reference` makes it; configurations drawing the same picture share it.
    std::string truthKey()
    {
        const std::string key = lightingModel(referenceScene(*_scene), _scene->pass.lighting);
        if (_truths.count(key)) return key;
        ReferenceOptions ref;
        ref.tolerance = _options.tolerance;
        ref.gradient = _options.normals;
        const auto start = std::chrono::steady_clock::now();
        const ReferenceSetup setup = referenceSetup(*_scene, _camera, ref);
        _truths[key] = renderReference(setup.scene, _camera, setup.options);
        std::cerr << "volren bench: reference '" << key << "' of " << _dataset << " at " << _width << "x" << _height
                  << " in " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s"
                  << std::endl;
        return key;
    }

    /// Medians over the frames after two warm-up frames (programs compiled, textures uploaded).
    BenchRow timeFrames(const std::string& name)
    {
        _renderer.setScene(_scene.get());
        const double freeBefore = freeGpuMemoryMb(*_renderer.state());
        std::vector<double> draw, gpu, cpu;
        for (int f = 0; f < _options.frames + 2; ++f) {
            const FrameTiming t = _renderer.renderFrame();
            if (!t.glErrors.empty()) throw std::runtime_error(name + ": GL error: " + t.glErrors.front());
            if (f < 2) continue;
            draw.push_back(t.drawMs);
            if (t.gpuMs >= 0.0) gpu.push_back(t.gpuMs);  // a timer value that cannot be true is left out
            cpu.push_back(t.cpuMs);
        }
        const double freeAfter = freeGpuMemoryMb(*_renderer.state());
        BenchRow row;
        row.dataset = _dataset;
        row.width = _width;
        row.height = _height;
        row.config = name;
        row.frameMs = median(draw);
        std::vector<double> deviation;
        for (double ms : draw) deviation.push_back(std::abs(ms - row.frameMs));
        row.frameNoiseMs = median(deviation);
        row.gpuMs = gpu.empty() ? -1.0 : median(gpu);
        row.cpuMs = median(cpu);
        row.textureMb = double(_renderer.volumeScene()->textureBytes()) / (1024.0 * 1024.0);
        row.gpuMemoryMb = freeBefore >= 0.0 && freeAfter >= 0.0 ? freeBefore - freeAfter : -1.0;
        row.keys = _renderer.volumeScene()->compositionKeys();
        return row;
    }

    /// Shadowed rows: the frame time while every light of the scene turns a little each frame (a
    /// light volume rebuilds each time), and the light volumes' last build and bytes per voxel.
    void measureLightMoves(BenchRow& row)
    {
        bool shadowed = false;
        for (const std::string& key : row.keys)
            shadowed = shadowed || (key.find("Shadowing=") != std::string::npos && key.find("Shadowing=null") == std::string::npos);
        std::vector<osg::Light*> lights;
        struct LightFinder : osg::NodeVisitor
        {
            LightFinder() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
            void apply(osg::LightSource& source) override
            {
                if (source.getLight()) found.push_back(source.getLight());
                traverse(source);
            }
            std::vector<osg::Light*> found;
        } finder;
        _scene->accept(finder);
        lights = finder.found;
        if (!shadowed || lights.empty()) return;
        std::vector<osg::Vec4> original;
        for (osg::Light* l : lights) original.push_back(l->getPosition());
        std::vector<double> draw;
        for (int f = 0; f < _options.frames; ++f) {
            const osg::Matrix turn = osg::Matrix::rotate(osg::DegreesToRadians(2.0 * (f + 1)), osg::Vec3(0, 1, 0));
            for (std::size_t i = 0; i < lights.size(); ++i) lights[i]->setPosition(original[i] * turn);
            draw.push_back(_renderer.renderFrame().drawMs);
        }
        for (std::size_t i = 0; i < lights.size(); ++i) lights[i]->setPosition(original[i]);
        row.lightMoveMs = median(draw);
        std::size_t bytes = 0, voxels = 0;
        for (const BuiltVolumeStatistics& s : _renderer.volumeScene()->builtVolumeStatistics()) {
            bytes += s.bytes;
            voxels += s.volumeVoxels;
            row.rebuildMs = std::max(row.rebuildMs, s.lastBuildSeconds * 1e3);
        }
        if (bytes > 0 && voxels > 0) row.auxBytesPerVoxel = double(bytes) / double(voxels);
    }

    const BenchOptions& _options;
    int _width, _height;
    OffscreenRenderer _renderer;
    osg::ref_ptr<VolumeScene> _scene;
    std::string _dataset;
    std::vector<VolumeNode*> _nodes;
    std::vector<std::pair<RenderSettings, osg::ref_ptr<Volume>>> _original;
    PassSettings _originalPass;
    ReferenceCamera _camera;
    std::map<std::string, ReferenceImage> _truths;  ///< by what is drawn (the lighting model)
};

/// The configurations --configs names, in its order (all of the matrix without it). A name not
/// in the matrix is read as settings: KEY=VALUE, several joined by '+' (checked when applied).
std::vector<BenchConfig> chosenConfigs(const BenchOptions& options)
{
    const std::vector<BenchConfig> matrix = defaultMatrix();
    if (options.only.empty()) return matrix;
    std::vector<BenchConfig> chosen;
    for (const std::string& name : options.only) {
        auto it = std::find_if(matrix.begin(), matrix.end(), [&](const BenchConfig& c) { return c.name == name; });
        if (it != matrix.end()) {
            chosen.push_back(*it);
            continue;
        }
        BenchConfig config{name, {}, "native"};
        std::stringstream parts(name);
        for (std::string part; std::getline(parts, part, '+');) {
            const std::size_t eq = part.find('=');
            if (eq == std::string::npos || eq == 0)
                throw UsageError("--configs: '" + name + "' is no configuration of the matrix nor KEY=VALUE[+KEY=VALUE...]");
            config.settings.emplace_back(part.substr(0, eq), part.substr(eq + 1));
        }
        chosen.push_back(config);
    }
    return chosen;
}

}  // namespace

int benchCommand(const std::vector<std::string>& args)
{
    const BenchOptions options = parseBenchOptions(args);
    const std::vector<BenchConfig> matrix = chosenConfigs(options);
    if (options.listConfigs) {  // the matrix: its rows, as --configs names them
        for (const BenchConfig& config : matrix) {
            std::cout << config.name;
            for (const auto& [key, value] : config.settings) std::cout << "  --set " << key << "=" << value;
            std::cout << "\n";
        }
        return 0;
    }
    BenchReport report;
    report.timingNote = "frame_ms: median draw time (first draw call to glFinish) over the frames after 2 warm-up "
                        "frames; gpu_ms: GL_TIME_ELAPSED (on Mesa llvmpipe it misses rasterisation); cpu_ms: the "
                        "whole frame";
    for (const std::string& input : options.inputs)
        for (const auto& [width, height] : options.sizes) {
            BenchRun run(input, width, height, options);
            report.context = run.context();
            for (const BenchConfig& config : matrix) report.rows.push_back(run.run(config));
            if (options.vtk) report.rows.push_back(run.runVtk());
        }
    writeReport(report, options.out);
    std::cout << "volren bench: wrote " << options.out << "/bench.{md,csv,json,png}" << std::endl;
    int beaten = 0;
    for (const BenchRow& r : report.rows)
        if (r.beatsDefault) {
            ++beaten;
            std::cout << "volren bench: " << r.dataset << " " << r.width << "x" << r.height << ": " << r.config
                      << " is faster and more accurate than the default (" << r.frameMs << " ms, RMSE " << r.error.rmse
                      << ")" << std::endl;
        }
    return options.checkFront && beaten > 0 ? 1 : 0;
}

}  // namespace volren::app
