#include "CommandLine.h"
#include "Commands.h"
#include "SweepHarness.h"

#include <volume_renderer/OffscreenRenderer.h>
#include <volume_renderer/Permutations.h>

#include <volume_model/ParseNumber.h>

#include <nlohmann/json.hpp>
#include <osg/GLObjects>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>

namespace volren::app {

namespace {

/// The composition that came closest to its bound against the reference.
struct Closest
{
    double ratio = 0.0, difference = 0.0, bound = 0.0;
    std::string key;
    nlohmann::json all = nlohmann::json::array();  ///< every comparison: key, difference, bound
};

/// The folder of --dump DIR for scene variant `scene`: DIR itself for the plain sweep scene,
/// DIR/<scene> for a variant (made when missing).
std::string dumpFolder(const std::string& dumpDir, const std::string& scene)
{
    const std::string dir = scene.empty() ? dumpDir : osgDB::concatPaths(dumpDir, scene);
    if (!osgDB::makeDirectory(dir)) throw std::runtime_error(dir + ": cannot make folder");
    return dir;
}

/// Writes composition `index`'s key and composed fragment source (INDEX.frag) and its RGBA float
/// image (INDEX.rgba, raw; the reference's, where compared, as INDEX.reference.rgba) into `dir`:
/// two runs' folders compare with `diff -r`.
void dumpComposition(const std::string& dir, std::size_t index, const VolumeScene& scene, const osg::Image& pixels)
{
    const std::string base = osgDB::concatPaths(dir, std::to_string(index));
    std::ofstream source(base + ".frag", std::ios::binary);
    for (const auto& [name, program] : scene.programs()) source << "// key: " << program->key << "\n" << program->fragmentSource;
    std::ofstream image(base + ".rgba", std::ios::binary);
    image.write(reinterpret_cast<const char*>(pixels.data()), std::streamsize(pixels.getTotalSizeInBytes()));
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
    bool list = false, compile = false, render = false, pairwise = false, check = true;
    bool modelled = false;  ///< only compositions whose every implementation has a reference model
    bool extremes = false;  ///< every composition also on the sweep scene's parameter extremes
    std::string variant;    ///< only the scene variants whose name holds this text (with --extremes)
    std::string sceneName;  ///< the scene variant being drawn (empty: the plain sweep scene)
    SweepLimits limits;
    unsigned int maxInstances = 1, maxLights = 1;
    std::size_t first = 0, count = std::size_t(-1), shard = 0, shards = 1;
    std::string statsFile, dumpDir;
    std::vector<std::pair<std::string, std::string>> where;  ///< --where SLOT=NAME: compositions choosing it
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
        else if (args[i] == "--modelled") o.modelled = true;
        else if (args[i] == "--extremes") o.extremes = true;
        else if (args[i] == "--variant") o.variant = text(i, "--variant needs a part of a variant's name");
        else if (args[i] == "--max-instances") o.maxInstances = unsigned(number(i, "--max-instances"));
        else if (args[i] == "--max-lights") o.maxLights = unsigned(number(i, "--max-lights"));
        else if (args[i] == "--first") o.first = number(i, "--first");
        else if (args[i] == "--count") o.count = number(i, "--count");
        else if (args[i] == "--shard") std::tie(o.shard, o.shards) = parseShard(i + 1 < args.size() ? args[++i] : "");
        else if (args[i] == "--dump") o.dumpDir = text(i, "--dump needs a folder");
        else if (args[i] == "--no-check") o.check = false;
        else if (args[i] == "--where") {
            const std::string& spec = text(i, "--where needs SLOT=NAME");
            const std::size_t eq = spec.find('=');
            if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
                throw UsageError("--where needs SLOT=NAME, got '" + spec + "'");
            o.where.emplace_back(spec.substr(0, eq), spec.substr(eq + 1));
        }
        else if (args[i] == "--time-limit") o.limits.frameMs = double(number(i, "--time-limit (ms)"));
        else if (args[i] == "--stats") o.statsFile = text(i, "--stats needs a file");
        else throw UsageError("permutations: unknown option '" + args[i] + "'");
    }
    if (o.maxInstances > 3 || o.maxLights > 4) throw UsageError("--max-instances is at most 3 and --max-lights at most 4");
    if (!o.dumpDir.empty() && !o.render) throw UsageError("--dump needs --render");
    if (!o.variant.empty() && !o.extremes) throw UsageError("--variant needs --extremes");
    return o;
}

/// The indices into the space this run takes: the pairwise cover or all, only those choosing the
/// --where implementations, every N-th of them for shard I/N (so each shard mixes all kinds of
/// composition). Without a cover or --where, nothing is listed: index k is computed.
class Selection
{
public:
    Selection(const PermutationSpace& space, const SweepOptions& o) : _shard(o.shard), _shards(o.shards)
    {
        _all = !o.pairwise && o.where.empty() && !o.modelled;
        if (_all) {
            _listed = space.size();
            return;
        }
        std::vector<std::size_t> indices;
        // The pairwise cover of the compositions choosing the --where implementations (and, with
        // --modelled, only modelled ones): every pair of values these may take, covered.
        auto allowed = [&o](const std::string& factor, const std::vector<std::string>& names) {
            if (o.modelled && !modelledValue(factor, names)) return false;
            for (const auto& [slot, name] : o.where)
                if (slot == factor && std::find(names.begin(), names.end(), name) == names.end()) return false;
            return true;
        };
        if (o.pairwise) indices = space.pairwiseCover(allowed);
        auto chooses = [&](std::size_t i) {
            const Composition c = space.at(i);
            if (o.modelled && !oracleBound(c).modelled) return false;
            for (const auto& [slot, name] : o.where)
                if (c.functionFor(slot) != name) return false;
            return true;
        };
        if (o.pairwise)
            std::erase_if(indices, [&](std::size_t i) { return !chooses(i); });
        else
            for (std::size_t i = 0; i < space.size(); ++i)
                if (chooses(i)) indices.push_back(i);
        _listed = indices.size();
        _indices = std::move(indices);
    }
    /// How many the run takes before --first and --count.
    std::size_t size() const { return _listed > _shard ? (_listed - _shard + _shards - 1) / _shards : 0; }
    /// The space index of the k-th.
    std::size_t at(std::size_t k) const
    {
        const std::size_t i = _shard + k * _shards;
        return _all ? i : _indices[i];
    }
    /// How many the cover or --where listed (the space's size when neither).
    std::size_t listed() const { return _listed; }

private:
    std::size_t _shard, _shards;
    bool _all = true;
    std::size_t _listed = 0;
    std::vector<std::size_t> _indices;
};

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

/// Draws `composition` (composed, compiled, linked at draw by llvmpipe) and checks the frame
/// (SweepHarness.h; with `check` off only a compile or link error fails it); `without` is the
/// scene's frame without its volume. A composition that passes is drawn again (the same image),
/// against its metamorphic variants (variantsOf), and against the CPU reference where every
/// implementation it chooses declares a model (oracleBound; the others counted in `unmodelled`
/// by the first implementation without one).
std::vector<SweepFailure> renderOne(const Composition& composition, std::size_t index, VolumeScene& scene,
                                    const CompositionPolicy& policy, OffscreenRenderer& renderer, const osg::Image& without,
                                    SweepOracle& oracle, const SweepOptions& o, std::vector<double>& ms,
                                    std::map<std::string, std::size_t>& checked,
                                    std::map<std::string, std::size_t>& unmodelled, Closest& closest)
{
    // One frame of `c`: its checks' failures, and a copy of the image.
    auto frame = [&](const Composition& c, bool timed) {
        scene.forcedComposition = c;
        const auto start = std::chrono::steady_clock::now();
        FrameTiming timing;
        std::string thrown;
        try {
            timing = renderer.renderFrame();
        } catch (const std::exception& e) {
            thrown = e.what();
        }
        const double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (timed) ms.push_back(elapsed);
        timing.cpuMs = elapsed;
        std::vector<SweepFailure> failures;
        if (!o.check) {
            if (!thrown.empty()) failures.push_back({"link", thrown});
        } else {
            failures = checkFrame(c, timing, thrown, *renderer.image(), without, o.limits);
        }
        return std::make_pair(failures, osg::ref_ptr<osg::Image>(new osg::Image(*renderer.image(), osg::CopyOp::DEEP_COPY_ALL)));
    };
    auto [failures, image] = frame(composition, true);
    if (!o.dumpDir.empty()) dumpComposition(dumpFolder(o.dumpDir, o.sceneName), index, scene, *image);
    if (!o.check || !failures.empty()) return failures;
    // Compares `a` with `b` for `check`, within `tolerance`.
    auto compare = [&failures, &checked](const std::string& check, const osg::Image& a, const osg::Image& b, double tolerance,
                                         const std::string& against) {
        ++checked[check];
        const double d = largestDifference(a, b);
        if (d > tolerance) {
            std::ostringstream detail;
            detail << "largest difference " << d << " > " << tolerance << " against " << against;
            failures.push_back({check, detail.str()});
        }
    };
    compare("repeat", *image, *frame(composition, false).second, 0.0, "the same composition drawn again");
    auto& settings = static_cast<VolumeNode*>(scene.getChild(0))->settings;
    const double termination = settings.earlyTerminationThreshold;
    for (const Variant& v : variantsOf(composition, policy)) {
        if (o.limits.refuses && o.limits.refuses(v.composition, scene)) continue;  // refuses this scene: nothing to compare
        if (v.withoutEarlyTermination) settings.earlyTerminationThreshold = 1.0;
        const osg::ref_ptr<osg::Image> original = v.withoutEarlyTermination ? frame(composition, false).second : image;
        auto [variantFailures, variant] = frame(v.composition, false);
        settings.earlyTerminationThreshold = termination;
        for (const SweepFailure& f : variantFailures)
            failures.push_back({v.check, "its variant " + v.composition.key() + " failed " + f.check + ": " + f.detail});
        if (variantFailures.empty()) compare(v.check, *original, *variant, v.tolerance, v.composition.key());
    }
    const OracleBound bound = oracleBound(composition);
    if (!bound.modelled) {
        ++unmodelled[bound.why];
        return failures;
    }
    ++checked["reference"];
    const ReferenceImage& reference = oracle.image(composition);
    if (!o.dumpDir.empty()) {  // beside its image: INDEX.reference.rgba, the same layout
        const std::vector<float> values(reference.rgba.begin(), reference.rgba.end());
        std::ofstream out(osgDB::concatPaths(dumpFolder(o.dumpDir, o.sceneName), std::to_string(index) + ".reference.rgba"),
                          std::ios::binary);
        out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
    }
    const double d = SweepOracle::largestDifference(*image, reference);
    const std::string key = composition.key() + (o.sceneName.empty() ? "" : " [scene: " + o.sceneName + "]");
    if (!(d / bound.bound <= closest.ratio))
        std::tie(closest.ratio, closest.difference, closest.bound, closest.key) = std::tuple(d / bound.bound, d, bound.bound, key);
    closest.all.push_back({{"key", composition.key()}, {"scene", o.sceneName}, {"difference", d}, {"bound", bound.bound}});
    if (!(d <= bound.bound)) {
        std::ostringstream detail;
        detail << "largest difference " << d << " > " << bound.bound << " against the CPU reference";
        failures.push_back({"reference", detail.str()});
    }
    return failures;
}

}  // namespace

int permutationsCommand(const std::vector<std::string>& args)
{
    const SweepOptions o = parseSweepOptions(args);
    const PermutationSpace space(ShaderFunctionRegistry::instance(), o.maxInstances, o.maxLights);
    const Selection indices(space, o);
    const std::size_t first = o.first;
    const std::size_t end = std::min(indices.size(), o.count == std::size_t(-1) ? indices.size() : first + o.count);
    std::cout << "volren permutations: " << space.size() << " valid compositions (instances <= " << o.maxInstances
              << ", lights <= " << o.maxLights << ")" << (o.pairwise ? ", pairwise cover of " : ", selected ")
              << indices.size() << "; this run: " << (end > first ? end - first : 0) << std::endl;
    if (o.list)
        for (std::size_t i = first; i < end; ++i) std::cout << space.at(indices.at(i)).key() << "\n";
    if (!o.compile) return 0;
    if (!o.dumpDir.empty() && !osgDB::makeDirectory(o.dumpDir)) throw std::runtime_error(o.dumpDir + ": cannot make folder");

    std::vector<double> ms;
    nlohmann::json resident = nlohmann::json::array();  // resident memory every memoryEvery compositions
    nlohmann::json failed = nlohmann::json::array();
    std::map<std::string, std::size_t> failedChecks;  // check -> compositions failing it
    std::map<std::string, std::size_t> checked;       // comparison check -> compositions compared
    std::map<std::string, std::size_t> unmodelled;    // why not compared with the reference -> compositions
    Closest closest;
    std::size_t failedCompositions = 0;
    std::size_t referenceImages = 0;
    double referenceSeconds = 0.0;
    // Each scene variant (only the plain sweep scene unless --extremes) draws every composition.
    for (const SweepVariant& variant : sweepVariants(o.render && o.extremes)) {
        if (!o.variant.empty() && variant.name.find(o.variant) == std::string::npos) continue;
        if (o.variant.empty() && !variant.openDefect.empty()) {
            std::cout << "not run: the variant '" << variant.name << "' (" << variant.openDefect
                      << "); --variant '" << variant.name << "' runs it" << std::endl;
            continue;
        }
        OffscreenRenderer renderer(variant.width, variant.height);
        osg::ref_ptr<VolumeScene> scene = sweepScene();
        scene->compositor().setCacheSize(0);  // a sweep never returns to a composition: keep none
        renderer.setScene(scene.get());
        placeSweepCamera(*renderer.camera());
        if (variant.apply) variant.apply(*scene, *renderer.camera());
        // The camera as placed: a frame may fit near and far to what it draws (the frame without
        // the volume to the geometry alone), and the reference must see the volume whole.
        const osg::Matrixd view = renderer.camera()->getViewMatrix(), projection = renderer.camera()->getProjectionMatrix();
        SweepOptions options = o;
        options.limits.drawn = variant.showsVolume;
        options.sceneName = variant.name;
        options.limits.refuses = variant.refuses;
        // The frame without the volume: what "nothing drawn" compares with.
        osg::ref_ptr<osg::Image> without;
        std::unique_ptr<SweepOracle> oracle;
        if (o.render) {
            osg::Node* volume = scene->getChild(0);
            volume->setNodeMask(0);
            renderer.renderFrame();
            without = new osg::Image(*renderer.image(), osg::CopyOp::DEEP_COPY_ALL);
            volume->setNodeMask(~0u);
            renderer.camera()->setProjectionMatrix(projection);
            oracle = std::make_unique<SweepOracle>(*scene, view, projection, variant.width, variant.height, osg::Vec3());
        }
        const std::string where = variant.name.empty() ? std::string() : " [scene: " + variant.name + "]";
        if (!o.dumpDir.empty() && without)  // the scene without its volume, as without.rgba
            std::ofstream(osgDB::concatPaths(dumpFolder(o.dumpDir, variant.name), "without.rgba"), std::ios::binary)
                .write(reinterpret_cast<const char*>(without->data()), std::streamsize(without->getTotalSizeInBytes()));
        for (std::size_t i = first; i < end; ++i) {
            const Composition composition = space.at(indices.at(i));
            std::vector<SweepFailure> failures;
            try {
                if (o.render)
                    failures = renderOne(composition, indices.at(i), *scene, space.policy(), renderer, *without, *oracle, options, ms,
                                         checked, unmodelled, closest);
                else if (std::string problem = compileOnly(composition, renderer, ms); !problem.empty())
                    failures.push_back({"link", problem});
            } catch (const std::exception& e) {
                failures.push_back({"compose", e.what()});
            }
            if (variant.refuses && variant.refuses(composition, *scene)) {  // it must fail with a refusal, and only so
                bool refused = failures.size() == 1 && failures[0].check == "compose";
                if (refused)
                    refused = std::any_of(variant.refusals.begin(), variant.refusals.end(), [&](const std::string& r) {
                        return failures[0].detail.find(r) != std::string::npos;
                    });
                std::string expected;
                for (const std::string& r : variant.refusals) expected += (expected.empty() ? "'" : " or '") + r + "'";
                failures = refused ? std::vector<SweepFailure>{}
                                   : std::vector<SweepFailure>{{"refused", "expected a compose error naming " + expected +
                                                                              (failures.empty() ? std::string(", drawn instead")
                                                                                                : ", got " + failures[0].check + ": " + failures[0].detail)}};
                ++checked["refused"];
            }
            failedCompositions += !failures.empty();
            for (const SweepFailure& f : failures) {
                ++failedChecks[f.check];
                failed.push_back({{"key", composition.key()}, {"check", f.check}, {"detail", f.detail + where}});
                std::string line = f.detail + where;  // one line per failure: a GLSL log's lines joined
                for (std::size_t at = 0; (at = line.find('\n', at)) != std::string::npos;) line.replace(at, 1, " | ");
                std::cout << "FAILED " << composition.key() << ": " << f.check << ": " << line << std::endl;
            }
            if ((i - first + 1) % memoryEvery == 0) {
                const double mb = residentMb();
                resident.push_back({{"done", i - first + 1}, {"resident_mb", mb}});
                std::cout << "  " << (i - first + 1) << " done, resident " << mb << " MB" << std::endl;
            }
        }
        if (oracle) {
            referenceImages += oracle->computed();
            referenceSeconds += oracle->seconds();
        }
    }
    std::cout << (o.render ? "rendered " : "compiled ") << ms.size() << ", failures " << failedCompositions << ", median "
              << (o.render ? "frame incl. compile" : "compile+link") << " " << median(ms) << " ms" << std::endl;
    if (!checked.empty()) {
        std::cout << "compared:";
        for (const auto& [check, n] : checked) std::cout << " " << check << " " << n;
        std::cout << std::endl;
    }
    if (o.render && o.check) {
        if (!closest.key.empty())
            std::cout << "closest to its bound against the reference: " << closest.difference << " of " << closest.bound
                      << " (" << closest.key << ")" << std::endl;
        std::cout << "reference images computed " << referenceImages << " in " << referenceSeconds
                  << " s; not compared with the reference:";
        std::size_t total = 0;
        for (const auto& [why, n] : unmodelled) total += n;
        std::cout << " " << total << std::endl;
        for (const auto& [why, n] : unmodelled) std::cout << "  " << n << "  " << why << std::endl;
    }
    if (!o.statsFile.empty()) {
        nlohmann::json stats = {{"valid_compositions", space.size()}, {"tested", ms.size()},
                                {"failures", failedCompositions}, {"failed", failed}, {"failed_checks", failedChecks},
                                {"checked", o.render && o.check}, {"compared", checked}, {"not_compared_with_reference", unmodelled},
                                {"closest_to_bound", {{"difference", closest.difference}, {"bound", closest.bound},
                                                      {"key", closest.key}}},
                                {"reference_seconds", referenceSeconds}, {"extremes", o.render && o.extremes},
                                {"reference_differences", closest.all}, {"median_ms", median(ms)},
                                {"mode", o.render ? "render" : "compile"}, {"pairwise", o.pairwise},
                                {"max_instances", o.maxInstances}, {"max_lights", o.maxLights},
                                {"shard", o.shard}, {"shards", o.shards},
                                {"resident", resident}, {"peak_resident_mb", peakResidentMb()}};
        std::ofstream(o.statsFile) << stats.dump(2) << "\n";
    }
    return failedCompositions == 0 ? 0 : 1;
}

}  // namespace volren::app
