#include "SweepHarness.h"

#include <volume_renderer/AuxKind.h>
#include <volume_renderer/BindContext.h>
#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/LoopBudget.h>
#include <volume_renderer/SampleDistance.h>
#include <volume_renderer/ShaderFunctionRegistry.h>
#include <volume_renderer/Slots.h>

#include <volume_model/ReferenceModel.h>

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipMaskNode.h>
#include <volume_model/ClipPlaneNode.h>

#include <osg/Geode>
#include <osg/Viewport>
#include <osg/LightSource>
#include <osg/ShapeDrawable>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace volren::app {

namespace {

/// The sweep field's soft ball leaning along x at (dx, dy, dz) in [-1, 1]^3 over the box.
double leaningBall(double dx, double dy, double dz)
{
    return std::max(0.0, 1.0 - std::sqrt(dx * dx + dy * dy + dz * dz)) * (0.75 + 0.25 * dx);
}

/// The opaque box through the volume (the depth clip's geometry), scaled by `s`.
osg::Drawable* opaqueBox(double s)
{
    const float f = float(s);
    return new osg::ShapeDrawable(new osg::Box(osg::Vec3(4.5f, 0.0f, -2.0f) * f, 3.0f * f, 14.0f * f, 1.0f * f));
}

/// The largest absolute difference between `n` values of `a` and of `b` (infinite where one is
/// not finite).
template <typename A, typename B>
double largestDifferenceOf(const A* a, const B* b, std::size_t n)
{
    double worst = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double d = std::abs(double(a[k]) - double(b[k]));
        worst = std::isfinite(d) ? std::max(worst, d) : HUGE_VAL;
    }
    return worst;
}

}  // namespace

osg::ref_ptr<VolumeScene> sweepScene()
{
    // A soft ball leaning along x (no axis mirrors its gradients onto another), 12 x 10 x 8
    // world units in voxels of 0.5, and a TF that gives it a lit shell and a denser core.
    osg::ref_ptr<Volume> volume = new Volume;
    const int nx = 24, ny = 20, nz = 16;
    volume->allocate(VoxelType::Float32, {nx, ny, nz});
    volume->setSpacing({0.5, 0.5, 0.5});
    auto* v = reinterpret_cast<float*>(volume->data());
    for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                const double dx = (x - 11.5) / 12, dy = (y - 9.5) / 10, dz = (z - 7.5) / 8;
                v[x + nx * (y + ny * z)] = float(leaningBall(dx, dy, dz) + 0.1 * dy * dz);
            }
    volume->dirty();
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(0, 0, 0, 0));
    tf->setPoint(0.2, osg::Vec4(0.9f, 0.6f, 0.3f, 0.0f));
    tf->setPoint(0.35, osg::Vec4(1.0f, 0.85f, 0.6f, 0.6f));
    tf->setPoint(1.0, osg::Vec4(0.6f, 0.8f, 1.0f, 0.3f));
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setName("sweep");
    node->setVolume(volume.get());
    node->setTransferFunction(tf.get());
    osg::ref_ptr<VolumeScene> scene = new VolumeScene;
    scene->addChild(node.get());
    osg::ref_ptr<osg::LightSource> light = new osg::LightSource;
    light->getLight()->setPosition(osg::Vec4(1, 1, 1, 0));
    scene->addChild(light.get());
    // One shape of every clip kind, each keeping most of the ball (the box is 12 x 10 x 8).
    osg::ref_ptr<ClipPlaneNode> plane = new ClipPlaneNode;
    plane->plane.set(1.0, 0.0, 0.0, 2.0);
    scene->addChild(plane.get());
    osg::ref_ptr<ClipBoxNode> box = new ClipBoxNode;
    box->box.set(-5, -4, -3, 5, 4, 3);
    scene->addChild(box.get());
    osg::ref_ptr<ClipEllipsoidNode> ellipsoid = new ClipEllipsoidNode;
    ellipsoid->radii.set(5.0, 4.5, 3.5);
    scene->addChild(ellipsoid.get());
    osg::ref_ptr<ClipMaskNode> mask = new ClipMaskNode;
    mask->mask = new Volume;
    mask->mask->allocate(VoxelType::UInt8, {6, 5, 4});  // over the whole box
    mask->mask->setSpacing({2.0, 2.0, 2.0});
    std::fill(mask->mask->data(), mask->mask->data() + 6 * 5 * 4, std::uint8_t(1));
    mask->mask->data()[0] = 0;  // one corner cell cut away
    mask->mask->dirty();
    scene->addChild(mask.get());
    // Opaque geometry through a part of the volume: what the depth clip and geometry shadows read.
    osg::ref_ptr<osg::Geode> geometry = new osg::Geode;
    geometry->addDrawable(opaqueBox(1.0));
    scene->addChild(geometry.get());
    return scene;
}

void placeSweepCamera(osg::Camera& camera, double scale)
{
    camera.setViewMatrixAsLookAt(osg::Vec3d(20, -25, 15) * scale, osg::Vec3d(), osg::Vec3d(0, 0, 1));
    camera.setProjectionMatrixAsPerspective(40, double(camera.getViewport() ? camera.getViewport()->aspectRatio() : 1.0),
                                            1.0 * scale, 100.0 * scale);
}

namespace {

VolumeNode& sweepNode(VolumeScene& scene) { return static_cast<VolumeNode&>(*scene.getChild(0)); }

/// The sweep volume's values stored as `type` (0..1 over the type's range, by the rescale).
void storeAs(VolumeScene& scene, VoxelType type, double range)
{
    const Volume& from = *sweepNode(scene).getVolume();
    osg::ref_ptr<Volume> to = new Volume;
    to->allocate(type, from.dims());
    to->setSpacing(from.spacing());
    to->setRescale(1.0 / range, 0.0);
    const auto* v = reinterpret_cast<const float*>(from.data());
    for (std::size_t i = 0; i < from.voxelCount(); ++i) {
        const double stored = std::round(std::clamp(double(v[i]), 0.0, 1.0) * range);
        if (type == VoxelType::UInt8) to->data()[i] = std::uint8_t(stored);
        else reinterpret_cast<std::uint16_t*>(to->data())[i] = std::uint16_t(stored);
    }
    to->dirty();
    sweepNode(scene).setVolume(to.get());
}

/// The TF's opacities all set to `alpha`.
void opacityEverywhere(VolumeScene& scene, float alpha)
{
    const TransferFunction& from = *sweepNode(scene).getTransferFunction();
    osg::ref_ptr<TransferFunction> to = new TransferFunction;
    for (const auto& [value, rgba] : from.points()) to->setPoint(value, osg::Vec4(rgba.r(), rgba.g(), rgba.b(), alpha));
    sweepNode(scene).setTransferFunction(to.get());
}

/// The sweep volume's values and its TF's points scaled by one factor, so that its largest
/// value is float's largest: the same picture, at the top of float's range.
void scaleValuesToFloatMax(VolumeScene& scene)
{
    Volume& volume = *sweepNode(scene).getVolume();
    auto* v = reinterpret_cast<float*>(volume.data());
    const float largest = *std::max_element(v, v + volume.voxelCount());
    const double scale = double(std::numeric_limits<float>::max()) / double(largest);
    for (std::size_t i = 0; i < volume.voxelCount(); ++i)
        v[i] = float(std::min(double(v[i]) * scale, double(std::numeric_limits<float>::max())));
    volume.dirty();
    const TransferFunction& from = *sweepNode(scene).getTransferFunction();
    osg::ref_ptr<TransferFunction> to = new TransferFunction;
    for (const auto& [value, rgba] : from.points()) to->setPoint(value * scale, rgba);
    sweepNode(scene).setTransferFunction(to.get());
}

/// A volume of `dims` over the sweep volume's box, its values the sweep field's shape.
void resample(VolumeScene& scene, const osg::Vec3i& dims)
{
    osg::ref_ptr<Volume> to = new Volume;
    to->allocate(VoxelType::Float32, dims);
    to->setSpacing({12.0 / dims.x(), 10.0 / dims.y(), 8.0 / dims.z()});
    auto* v = reinterpret_cast<float*>(to->data());
    for (int z = 0; z < dims.z(); ++z)
        for (int y = 0; y < dims.y(); ++y)
            for (int x = 0; x < dims.x(); ++x) {
                const double dx = 2.0 * (x + 0.5) / dims.x() - 1.0, dy = 2.0 * (y + 0.5) / dims.y() - 1.0,
                             dz = 2.0 * (z + 0.5) / dims.z() - 1.0;
                v[x + dims.x() * (y + dims.y() * z)] = float(leaningBall(dx, dy, dz) + 0.5 * (dims.x() == 1));
            }
    to->dirty();
    sweepNode(scene).setVolume(to.get());
}

/// The whole scene (volume spacing, clip shapes, the opaque box, the camera) scaled by `s`.
void scaleScene(VolumeScene& scene, osg::Camera& camera, double s)
{
    Volume& volume = *sweepNode(scene).getVolume();
    volume.setSpacing(volume.spacing() * s);
    for (unsigned int i = 0; i < scene.getNumChildren(); ++i) {
        osg::Node* child = scene.getChild(i);
        if (auto* plane = dynamic_cast<ClipPlaneNode*>(child)) {
            plane->plane[3] *= s;
        } else if (auto* box = dynamic_cast<ClipBoxNode*>(child)) {
            box->box.set(box->box._min * s, box->box._max * s);
        } else if (auto* ellipsoid = dynamic_cast<ClipEllipsoidNode*>(child)) {
            ellipsoid->center *= s;
            ellipsoid->radii *= s;
        } else if (auto* mask = dynamic_cast<ClipMaskNode*>(child)) {
            mask->mask->setSpacing(mask->mask->spacing() * s);
        } else if (auto* geode = dynamic_cast<osg::Geode*>(child)) {
            geode->removeDrawables(0, geode->getNumDrawables());
            geode->addDrawable(opaqueBox(s));
        }
    }
    placeSweepCamera(camera, s);
}

/// Runs `read` on the binding context of the sweep node of `scene` for composition `c`, with
/// c.lightCount lights and its level 0: what the declarations' costs and sizes read.
template <typename Read>
auto withBindContext(const Composition& c, VolumeScene& scene, Read read)
{
    VolumeNode& node = sweepNode(scene);
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    const std::map<std::string, int> units;
    BindContext context{.node = node,
                        .volume = *node.getVolume(),
                        .transfer = *node.getTransferFunction(),
                        .settings = node.settings,
                        .sampleDistance = effectiveSampleDistance(node),
                        .stateSet = *state,
                        .textureUnits = units,
                        .boxSize = node.getVolume()->worldSize()};
    context.lights.resize(std::size_t(c.lightCount), LightInfo{osg::Vec4d(0, 0, 1, 0), osg::Vec3d(1, 1, 1)});
    for (const SlotInfo& slot : slots()) context.chosen[slot.name] = c.functionFor(slot.name);
    return read(context);
}

/// Whether a view ray of `c` through the sweep node of `scene` takes more loop iterations than
/// the driver lets a pixel run (LoopBudget.h): the pass refuses it, from what its
/// implementations declare (ShaderFunction::loops).
bool beyondTheLoopLimit(const Composition& c, VolumeScene& scene)
{
    return withBindContext(c, scene, [](const BindContext& context) { return !viewRayWithinLoopLimit(context); });
}

/// Whether an implementation of `c` needs an auxiliary volume built at a size (AuxBuild::dims,
/// for level 0 of the sweep node of `scene`) beyond the driver's largest 3D texture.
bool needsABuiltVolumeBeyondTheLargestTexture(const Composition& c, VolumeScene& scene)
{
    return withBindContext(c, scene, [](const BindContext& context) {
        const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
        for (const auto& [slot, name] : context.chosen)
            if (const ShaderFunction* f = registry.find(slot, name))
                for (const AuxKind* kind : registry.auxKindsOf(*f))
                    if (kind->build && exceedsLargest3DTexture(kind->build->dims(context.volume.dims(), context)))
                        return true;
        return false;
    });
}

}  // namespace

std::vector<SweepVariant> sweepVariants(bool extremes)
{
    std::vector<SweepVariant> variants = {{}};
    if (!extremes) return variants;
    auto add = [&](std::string name, std::function<void(VolumeScene&, osg::Camera&)> apply) {
        variants.push_back({.name = std::move(name), .apply = std::move(apply)});
    };
    add("8-bit data", [](VolumeScene& s, osg::Camera&) { storeAs(s, VoxelType::UInt8, 255.0); });
    add("16-bit data", [](VolumeScene& s, osg::Camera&) { storeAs(s, VoxelType::UInt16, 65535.0); });
    add("values to float's largest", [](VolumeScene& s, osg::Camera&) { scaleValuesToFloatMax(s); });
    add("NaN voxels", [](VolumeScene& s, osg::Camera&) {
        Volume& volume = *sweepNode(s).getVolume();
        auto* v = reinterpret_cast<float*>(volume.data());
        for (std::size_t i = 0; i < volume.voxelCount(); i += 37) v[i] = std::numeric_limits<float>::quiet_NaN();
        volume.dirty();
    });
    variants.push_back({.name = "TF opacity 0", .showsVolume = false,
                        .apply = [](VolumeScene& s, osg::Camera&) { opacityEverywhere(s, 0.0f); }});
    add("TF opacity 1", [](VolumeScene& s, osg::Camera&) { opacityEverywhere(s, 1.0f); });
    variants.push_back({.name = "steps of 1/1000 voxel",
                        .apply = [](VolumeScene& s, osg::Camera&) { sweepNode(s).settings.sampleDistanceFactor = 0.001; },
                        // 35,100 view samples through the ball, and lit ones at least a light loop's
                        // iteration more per sample: over 70,000 iterations a pixel, beyond a driver
                        // that ends a pixel's loops after 65,535 (llvmpipe).
                        .refuses = beyondTheLoopLimit,
                        .refusals = {"loop iterations"}});
    variants.push_back({.name = "steps of 10 voxels",
                        .apply = [](VolumeScene& s, osg::Camera&) { sweepNode(s).settings.sampleDistanceFactor = 10.0; },
                        .openDefect = "#38: 13 of 13 unlit modelled compositions differ from the reference by 0.73-0.95 "
                                      "(two or three samples a ray: pixels where the GPU's samples miss the ball and the "
                                      "reference's hit it; their sample positions are not yet the same at coarse steps)"});
    add("spacing 1e-9", [](VolumeScene& s, osg::Camera& c) { scaleScene(s, c, 2e-9); });
    add("spacing 1e12", [](VolumeScene& s, osg::Camera& c) { scaleScene(s, c, 2e12); });
    add("1x1x1 volume", [](VolumeScene& s, osg::Camera&) { resample(s, {1, 1, 1}); });
    variants.push_back({.name = "4096x4x4 volume",
                        .apply = [](VolumeScene& s, osg::Camera&) { resample(s, {4096, 4, 4}); },
                        // Beyond the largest 3D texture of every driver of today's kind: a storage
                        // that does not keep within the limits (traits.withinBudget) refuses it, and
                        // so does a built auxiliary volume at the sampled level's size (the cones'
                        // opacity mip chain). 11,982 view samples (a step of half its 0.003-unit
                        // spacing) and central-9's 12 taps per lit sample: beyond 65,535 iterations.
                        .refuses =
                            [](const Composition& c, VolumeScene& s) {
                                const ShaderFunction* storage =
                                    ShaderFunctionRegistry::instance().find("VolumeStorage", c.functionFor("VolumeStorage"));
                                return (storage && !storage->traits.withinBudget && !storage->needs.empty()) ||  // null reads nothing
                                       needsABuiltVolumeBeyondTheLargestTexture(c, s) || beyondTheLoopLimit(c, s);
                            },
                        .refusals = {"beyond this driver's largest 3D texture", "loop iterations"}});
    add("camera inside", [](VolumeScene&, osg::Camera& c) {
        c.setViewMatrixAsLookAt(osg::Vec3d(-1.0, 1.0, 0.5), osg::Vec3d(20, -25, 15), osg::Vec3d(0, 0, 1));
        c.setProjectionMatrixAsPerspective(60, 1.0, 0.01, 100.0);
    });
    variants.push_back({.name = "1x1 viewport", .width = 1, .height = 1});
    variants.push_back({.name = "4096x4 viewport", .width = 4096, .height = 4, .apply = [](VolumeScene&, osg::Camera& c) {
                            c.setProjectionMatrixAsPerspective(40, 1.0, 1.0, 100.0);  // stretched: the volume spans it
                        }});
    return variants;
}

bool showsVolume(const Composition& composition)
{
    for (const char* slot : {"RaySetup", "VolumeStorage", "Reconstruction"})
        if (composition.functionFor(slot) == "null") return false;
    const ShaderFunction* traversal =
        ShaderFunctionRegistry::instance().find("RayTraversal", composition.functionFor("RayTraversal"));
    return traversal && traversal->traits.sharesRayAs == "emission_absorption";
}

std::vector<Variant> variantsOf(const Composition& composition, const CompositionPolicy& policy)
{
    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    std::vector<Variant> variants;
    auto add = [&](const std::string& check, const std::string& slot, const std::string& name, double tolerance,
                   bool withoutTermination) {
        Composition v = composition;
        v.choice[slot] = name;
        if (policy.isValid(v)) variants.push_back({check, v, tolerance, withoutTermination});
    };
    const auto chosen = [&](const char* slot) { return registry.find(slot, composition.functionFor(slot)); };
    if (const ShaderFunction* a = chosen("Acceleration"); a && !a->traits.skips.empty() && !a->traits.approximates)
        add("acceleration", "Acceleration", "null", 0.0, false);
    if (const ShaderFunction* storage = chosen("VolumeStorage"); storage && storage->name != "null")
        for (const std::string& other : registry.names("VolumeStorage"))
            if (other != storage->name && other != "null") add("storage", "VolumeStorage", other, 1e-4, false);
    // Front to back against back to front takes the same samples, unless an approximating
    // Acceleration merges them (adaptive: runs found from each end take different midpoints,
    // 0.012 apart on a 1x1x1 volume whose every cell is homogeneous).
    const ShaderFunction* acceleration = chosen("Acceleration");
    if (const ShaderFunction* t = chosen("RayTraversal");
        t && t->traits.sharesRayAs == "emission_absorption" && !(acceleration && acceleration->traits.approximates))
        for (const std::string& other : registry.names("RayTraversal")) {
            const ShaderFunction* o = registry.find("RayTraversal", other);
            if (other != t->name && o->traits.sharesRayAs == t->traits.sharesRayAs) add("traversal", "RayTraversal", other, 1e-4, true);
        }
    return variants;
}

double largestDifference(const osg::Image& a, const osg::Image& b)
{
    return largestDifferenceOf(reinterpret_cast<const float*>(a.data()), reinterpret_cast<const float*>(b.data()),
                               std::size_t(a.s()) * std::size_t(a.t()) * 4);
}

namespace {

/// Whether `model` (an implementation's declaration, null: none) is one the reference computes.
bool hasModel(const ReferenceModel* model) { return model && model->fidelity != ReferenceModel::Fidelity::None; }

}  // namespace

OracleBound oracleBound(const Composition& composition)
{
    OracleBound verdict{true, oracleBase, {}};
    auto account = [&](const std::string& slot, const std::string& name) {
        const ReferenceModel* model = ReferenceModelCatalog::instance().find(slot, name);
        if (verdict.modelled && !hasModel(model)) {
            verdict.modelled = false;
            verdict.why = slot + " " + name + ": " + (model ? model->why : std::string("declares no reference model"));
        }
        if (model && model->fidelity == ReferenceModel::Fidelity::Approximate) verdict.bound += model->bound;
    };
    for (const SlotInfo& slot : slots()) {
        if (slot.isTemplate)
            for (const std::string& name : composition.instancesOf(slot.name)) account(slot.name, name);
        else
            account(slot.name, composition.functionFor(slot.name));
    }
    if (!verdict.modelled) verdict.bound = 0.0;
    return verdict;
}

bool modelledValue(const std::string& factor, const std::vector<std::string>& names)
{
    if (factor == "lights") return true;
    return std::all_of(names.begin(), names.end(), [&](const std::string& name) {
        return hasModel(ReferenceModelCatalog::instance().find(factor, name));
    });
}

SweepOracle::SweepOracle(VolumeScene& scene, const osg::Matrixd& view, const osg::Matrixd& projection, int width,
                         int height, const osg::Vec3& background)
    : _policy(scene.policy()), _camera{view, projection, width, height}
{
    ReferenceOptions options;
    options.background = osg::Vec3d(background);
    _setup = referenceSetup(scene, _camera, options);
}

const ReferenceImage& SweepOracle::image(const Composition& composition)
{
    // What decides the reference: the implementations (their models), the clip kinds the
    // instances bind, the number of lights shaded with.
    std::set<std::string> kinds;
    for (const char* slot : {"ClipPosition", "ClipRay"})
        for (const std::string& name : composition.instancesOf(slot))
            if (const ShaderFunction* f = ShaderFunctionRegistry::instance().find(slot, name)) kinds.insert(f->traits.clipKind);
    std::string key = std::to_string(composition.lightCount) + ";";
    for (const auto& [slot, name] : composition.choice) key += slot + "=" + name + ";";
    for (const std::string& kind : kinds) key += "[" + kind + "]";
    if (auto it = _cache.find(key); it != _cache.end()) return it->second;

    ReferenceSetup setup = _setup;
    for (ReferenceScene::Placed& placed : setup.scene.volumes) applyChoice(placed, ChosenComposition{composition, {}}, _policy);
    std::erase_if(setup.scene.clips, [&](const ReferenceScene::Placed& clip) {
        const auto* node = dynamic_cast<const ClipNode*>(clip.node.get());
        return !node || !kinds.count(node->clipKind());
    });
    if (!kinds.count("depth"))  // rays run through the geometry, composited over its colour
        std::fill(setup.options.geometryDepth.begin(), setup.options.geometryDepth.end(), 1.0f);
    if (composition.lightCount == 0) setup.scene.lights.clear();
    const auto start = std::chrono::steady_clock::now();
    ReferenceImage reference = renderReference(setup.scene, _camera, setup.options);
    _seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return _cache.emplace(key, std::move(reference)).first->second;
}

double SweepOracle::largestDifference(const osg::Image& gpu, const ReferenceImage& reference)
{
    return largestDifferenceOf(reinterpret_cast<const float*>(gpu.data()), reference.rgba.data(),
                               std::size_t(gpu.s()) * std::size_t(gpu.t()) * 4);
}

namespace {

std::string joined(const std::vector<std::string>& messages)
{
    std::string out;
    for (const std::string& m : messages) out += (out.empty() ? "" : "; ") + m;
    return out;
}

}  // namespace

std::vector<SweepFailure> checkFrame(const Composition& composition, const FrameTiming& timing, const std::string& thrown,
                                     const osg::Image& image, const osg::Image& without, const SweepLimits& limits)
{
    std::vector<SweepFailure> failures;
    if (!thrown.empty()) failures.push_back({"link", thrown});
    if (!timing.drawErrors.empty()) failures.push_back({"compose", joined(timing.drawErrors)});
    if (!timing.glErrors.empty()) failures.push_back({"gl", joined(timing.glErrors)});
    const auto* px = reinterpret_cast<const float*>(image.data());
    const auto* bg = reinterpret_cast<const float*>(without.data());
    const std::size_t values = std::size_t(image.s()) * std::size_t(image.t()) * 4;
    std::size_t nonFinite = 0;
    double change = 0.0;  // the largest difference from the frame without the volume
    for (std::size_t k = 0; k < values; ++k) {
        if (!std::isfinite(px[k])) ++nonFinite;
        else change = std::max(change, double(std::abs(px[k] - bg[k])));
    }
    if (nonFinite > 0) failures.push_back({"finite", std::to_string(nonFinite) + " NaN or Inf values > 0"});
    if (thrown.empty() && timing.drawErrors.empty() && limits.drawn && showsVolume(composition) && !(change > 1e-4)) {
        std::ostringstream detail;
        detail << "largest change from the frame without the volume " << change << " <= 1e-4";
        failures.push_back({"drawn", detail.str()});
    }
    if (timing.cpuMs > limits.frameMs) {
        std::ostringstream detail;
        detail << timing.cpuMs << " ms > " << limits.frameMs << " ms";
        failures.push_back({"time", detail.str()});
    }
    return failures;
}

}  // namespace volren::app
