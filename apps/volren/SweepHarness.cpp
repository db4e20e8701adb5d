#include "SweepHarness.h"

#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/ClipBoxNode.h>
#include <volume_model/ClipEllipsoidNode.h>
#include <volume_model/ClipMaskNode.h>
#include <volume_model/ClipPlaneNode.h>

#include <osg/Geode>
#include <osg/LightSource>
#include <osg/ShapeDrawable>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace volren::app {

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
    mask->mask->allocate(VoxelType::UInt8, {6, 5, 4});
    mask->mask->setSpacing({2.0, 2.0, 2.0});
    std::fill(mask->mask->data(), mask->mask->data() + 6 * 5 * 4, std::uint8_t(1));
    mask->mask->data()[0] = 0;  // one corner cell cut away
    mask->mask->dirty();
    scene->addChild(mask.get());
    // Opaque geometry through a part of the volume: what the depth clip and geometry shadows read.
    osg::ref_ptr<osg::Geode> geometry = new osg::Geode;
    geometry->addDrawable(new osg::ShapeDrawable(new osg::Box(osg::Vec3(4.5f, 0.0f, -2.0f), 3.0f, 14.0f, 1.0f)));
    scene->addChild(geometry.get());
    return scene;
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
    if (const ShaderFunction* t = chosen("RayTraversal"); t && t->traits.sharesRayAs == "emission_absorption")
        for (const std::string& other : registry.names("RayTraversal")) {
            const ShaderFunction* o = registry.find("RayTraversal", other);
            if (other != t->name && o->traits.sharesRayAs == t->traits.sharesRayAs) add("traversal", "RayTraversal", other, 1e-4, true);
        }
    return variants;
}

double largestDifference(const osg::Image& a, const osg::Image& b)
{
    const auto* pa = reinterpret_cast<const float*>(a.data());
    const auto* pb = reinterpret_cast<const float*>(b.data());
    double worst = 0.0;
    for (std::size_t k = 0, n = std::size_t(a.s()) * std::size_t(a.t()) * 4; k < n; ++k) {
        const double d = std::abs(double(pa[k]) - double(pb[k]));
        worst = std::isfinite(d) ? std::max(worst, d) : HUGE_VAL;
    }
    return worst;
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
    if (thrown.empty() && timing.drawErrors.empty() && showsVolume(composition) && !(change > 1e-4)) {
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
