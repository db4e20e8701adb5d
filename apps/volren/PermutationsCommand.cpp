#include "CommandLine.h"
#include "Commands.h"

#include <volume_renderer/OffscreenRenderer.h>
#include <volume_renderer/Permutations.h>

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipPlaneNode.h>
#include <volume_model/ParseNumber.h>

#include <nlohmann/json.hpp>
#include <osg/GLObjects>
#include <osg/LightSource>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <tuple>

namespace volren::app {

namespace {

/// A small scene that gives every slot something to do: a float volume (a soft ball), a TF,
/// a light, a clip plane and a clip box.
osg::ref_ptr<VolumeScene> sweepScene()
{
    osg::ref_ptr<Volume> volume = new Volume;
    volume->allocate(VoxelType::Float32, {12, 10, 8});
    auto* v = reinterpret_cast<float*>(volume->data());
    for (int z = 0; z < 8; ++z)
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 12; ++x) {
                const double dx = (x - 5.5) / 6, dy = (y - 4.5) / 5, dz = (z - 3.5) / 4;
                v[x + 12 * (y + 10 * z)] = float(std::max(0.0, 1.0 - std::sqrt(dx * dx + dy * dy + dz * dz)));
            }
    volume->dirty();
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(0, 0, 0, 0));
    tf->setPoint(1.0, osg::Vec4(1, 0.8f, 0.6f, 0.5f));
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setName("sweep");
    node->setVolume(volume.get());
    node->setTransferFunction(tf.get());
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(node.get());
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(1, 1, 1, 0));
    scene->addChild(light.get());
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(1.0, 0.0, 0.0, 2.0);
    scene->addChild(plane.get());
    osg::ref_ptr<ClipBoxNode> box = new ClipBoxNode;
    box->box.set(-5, -4, -3, 5, 4, 3);
    scene->addChild(box.get());
    return scene;
}

/// Writes composition `index`'s key and composed fragment source (INDEX.frag) and its 8x8 RGBA
/// float image (INDEX.rgba, raw) into `dir`: two runs' folders compare with `diff -r`.
void dumpComposition(const std::string& dir, std::size_t index, const VolumeScene& scene, const float* pixels)
{
    const std::string base = osgDB::concatPaths(dir, std::to_string(index));
    std::ofstream source(base + ".frag", std::ios::binary);
    for (const auto& [name, program] : scene.programs()) source << "// key: " << program->key << "\n" << program->fragmentSource;
    std::ofstream image(base + ".rgba", std::ios::binary);
    image.write(reinterpret_cast<const char*>(pixels), 8 * 8 * 4 * sizeof(float));
    if (!source || !image) throw std::runtime_error(base + ": cannot write the dump");
}

/// A line of /proc/self/status ("VmRSS", "VmHWM") in MiB, or -1.
double statusMb(const std::string& field)
{
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind(field + ":", 0) == 0) return std::stod(line.substr(field.size() + 1)) / 1024.0;  // in kB
    return -1.0;
}
double residentMb() { return statusMb("VmRSS"); }
double peakResidentMb() { return statusMb("VmHWM"); }

/// How often the sweep reports its resident memory.
constexpr std::size_t memoryEvery = 500;

double median(std::vector<double> v)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

/// The options of `volren permutations`.
struct SweepOptions
{
    bool list = false, compile = false, render = false, pairwise = false;
    unsigned int maxInstances = 1, maxLights = 1;
    std::size_t first = 0, count = std::size_t(-1), shard = 0, shards = 1;
    std::string statsFile, dumpDir;
};

/// "I/N" of --shard.
std::pair<std::size_t, std::size_t> parseShard(const std::string& spec)
{
    const std::size_t slash = spec.find('/');
    double a = 0, b = 0;
    if (slash == std::string::npos || !parseFiniteNumber(spec.substr(0, slash), a) ||
        !parseFiniteNumber(spec.substr(slash + 1), b) || b < 1 || a < 0 || a >= b || a != std::floor(a) ||
        b != std::floor(b))
        throw UsageError("--shard needs I/N with 0 <= I < N, got '" + spec + "'");
    return {std::size_t(a), std::size_t(b)};
}

SweepOptions parseSweepOptions(const std::vector<std::string>& args)
{
    SweepOptions o;
    auto number = [&](std::size_t& i, const std::string& what) {
        double v = 0;
        if (i + 1 >= args.size() || !parseFiniteNumber(args[i + 1], v) || v < 0 || v != std::floor(v))
            throw UsageError(what + " needs a whole number >= 0");
        ++i;
        return std::size_t(v);
    };
    auto text = [&](std::size_t& i, const std::string& what) -> const std::string& {
        if (i + 1 >= args.size()) throw UsageError(what);
        return args[++i];
    };
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--list") o.list = true;
        else if (args[i] == "--compile") o.compile = true;
        else if (args[i] == "--render") o.render = o.compile = true;
        else if (args[i] == "--pairwise") o.pairwise = true;
        else if (args[i] == "--max-instances") o.maxInstances = unsigned(number(i, "--max-instances"));
        else if (args[i] == "--max-lights") o.maxLights = unsigned(number(i, "--max-lights"));
        else if (args[i] == "--first") o.first = number(i, "--first");
        else if (args[i] == "--count") o.count = number(i, "--count");
        else if (args[i] == "--shard") std::tie(o.shard, o.shards) = parseShard(i + 1 < args.size() ? args[++i] : "");
        else if (args[i] == "--dump") o.dumpDir = text(i, "--dump needs a folder");
        else if (args[i] == "--stats") o.statsFile = text(i, "--stats needs a file");
        else throw UsageError("permutations: unknown option '" + args[i] + "'");
    }
    if (o.maxInstances > 3 || o.maxLights > 4) throw UsageError("--max-instances is at most 3 and --max-lights at most 4");
    if (!o.dumpDir.empty() && !o.render) throw UsageError("--dump needs --render");
    return o;
}

/// Indices into `space` this run takes: the pairwise cover or all, every N-th of them for shard
/// I/N (so each shard mixes all kinds of composition).
std::vector<std::size_t> selection(const PermutationSpace& space, const SweepOptions& o)
{
    std::vector<std::size_t> indices;
    if (o.pairwise) indices = space.pairwiseCover();
    else
        for (std::size_t i = 0; i < space.size(); ++i) indices.push_back(i);
    if (o.shards <= 1) return indices;
    std::vector<std::size_t> mine;
    for (std::size_t i = o.shard; i < indices.size(); i += o.shards) mine.push_back(indices[i]);
    return mine;
}

/// Composes, compiles and links `composition` without drawing; returns what went wrong, if anything.
std::string compileOnly(const Composition& composition, OffscreenRenderer& renderer, std::vector<double>& ms)
{
    ShaderCompositor compositor;  // of its own: a shared cache would hold every program of the sweep
    auto program = compositor.program(composition);
    const auto start = std::chrono::steady_clock::now();
    program->program->compileGLObjects(*renderer.state());
    osg::Program::PerContextProgram* pcp = program->program->getPCP(*renderer.state());
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    std::string problem;
    if (!pcp || !pcp->isLinked()) {
        std::string log;
        program->program->getGlProgramInfoLog(renderer.state()->getContextID(), log);
        problem = "link failed: " + ShaderCompositor::explainLog(log, *program);
    }
    program->program->releaseGLObjects(renderer.state());
    for (const auto& [member, build] : program->builds) {  // its compute builds
        if (!problem.empty()) break;
        build.program->compileGLObjects(*renderer.state());
        const osg::Program::PerContextProgram* buildPcp = build.program->getPCP(*renderer.state());
        if (!buildPcp || !buildPcp->isLinked()) {
            std::string log;
            build.program->getGlProgramInfoLog(renderer.state()->getContextID(), log);
            problem = "build program link failed: " + ShaderCompositor::explainLog(log, build.sourceNames);
        }
        build.program->releaseGLObjects(renderer.state());
    }
    osg::flushAllDeletedGLObjects(renderer.state()->getContextID());  // no frames flush them here
    return problem;
}

/// Draws `composition` (composed, compiled, linked at draw by llvmpipe); returns what went wrong.
std::string renderOne(const Composition& composition, std::size_t index, VolumeScene& scene,
                      OffscreenRenderer& renderer, const std::string& dumpDir, std::vector<double>& ms)
{
    scene.forcedComposition = composition;
    const auto start = std::chrono::steady_clock::now();
    renderer.renderFrame();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    const auto* px = reinterpret_cast<const float*>(renderer.image()->data());
    std::string problem;
    for (int k = 0; k < 8 * 8 * 4; ++k)
        if (!std::isfinite(px[k])) problem = "NaN or Inf pixel";
    if (!dumpDir.empty()) dumpComposition(dumpDir, index, scene, px);
    return problem;
}

}  // namespace

int permutationsCommand(const std::vector<std::string>& args)
{
    const SweepOptions o = parseSweepOptions(args);
    const PermutationSpace space(ShaderFunctionRegistry::instance(), o.maxInstances, o.maxLights);
    const std::vector<std::size_t> indices = selection(space, o);
    const std::size_t first = o.first;
    const std::size_t end = std::min(indices.size(), o.count == std::size_t(-1) ? indices.size() : first + o.count);
    std::cout << "volren permutations: " << space.size() << " valid compositions (instances <= " << o.maxInstances
              << ", lights <= " << o.maxLights << ")" << (o.pairwise ? ", pairwise cover of " : ", selected ")
              << indices.size() << "; this run: " << (end > first ? end - first : 0) << std::endl;
    if (o.list)
        for (std::size_t i = first; i < end; ++i) std::cout << space.at(indices[i]).key() << "\n";
    if (!o.compile) return 0;
    if (!o.dumpDir.empty() && !osgDB::makeDirectory(o.dumpDir)) throw std::runtime_error(o.dumpDir + ": cannot make folder");

    OffscreenRenderer renderer(8, 8);
    osg::ref_ptr<VolumeScene> scene = sweepScene();
    scene->compositor().setCacheSize(0);  // a sweep never returns to a composition: keep none
    renderer.setScene(scene.get());
    renderer.camera()->setViewMatrixAsLookAt(osg::Vec3d(20, -25, 15), osg::Vec3d(), osg::Vec3d(0, 0, 1));
    renderer.camera()->setProjectionMatrixAsPerspective(40, 1, 1, 100);
    std::vector<double> ms;
    nlohmann::json resident = nlohmann::json::array();  // resident memory every memoryEvery compositions
    nlohmann::json failed = nlohmann::json::array();
    for (std::size_t i = first; i < end; ++i) {
        const Composition composition = space.at(indices[i]);
        std::string problem;
        try {
            problem = o.render ? renderOne(composition, indices[i], *scene, renderer, o.dumpDir, ms)
                               : compileOnly(composition, renderer, ms);
        } catch (const std::exception& e) {
            problem = e.what();
        }
        if (!problem.empty()) {
            failed.push_back({{"key", composition.key()}, {"error", problem}});
            std::cout << "FAILED " << composition.key() << "\n  " << problem << std::endl;
        }
        if ((i - first + 1) % memoryEvery == 0) {
            const double mb = residentMb();
            resident.push_back({{"done", i - first + 1}, {"resident_mb", mb}});
            std::cout << "  " << (i - first + 1) << " done, resident " << mb << " MB" << std::endl;
        }
    }
    std::cout << (o.render ? "rendered " : "compiled ") << ms.size() << ", failures " << failed.size() << ", median "
              << (o.render ? "frame incl. compile" : "compile+link") << " " << median(ms) << " ms" << std::endl;
    if (!o.statsFile.empty()) {
        nlohmann::json stats = {{"valid_compositions", space.size()}, {"tested", ms.size()},
                                {"failures", failed.size()}, {"failed", failed}, {"median_ms", median(ms)},
                                {"mode", o.render ? "render" : "compile"}, {"pairwise", o.pairwise},
                                {"max_instances", o.maxInstances}, {"max_lights", o.maxLights},
                                {"shard", o.shard}, {"shards", o.shards},
                                {"resident", resident}, {"peak_resident_mb", peakResidentMb()}};
        std::ofstream(o.statsFile) << stats.dump(2) << "\n";
    }
    return failed.empty() ? 0 : 1;
}

}  // namespace volren::app
