#include <volume_renderer/BindContext.h>
#include <volume_renderer/GraphicsDriver.h>
#include <volume_renderer/LoopBudget.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/Volume.h>
#include <volume_model/VolumeNode.h>

#include <osg/Notify>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace volren {

namespace {

/// Most steps one shadow march takes, whatever its step (Shadowing/ray.glsl's cap).
constexpr double maxShadowSteps = 16384.0;
/// Part of the limit a march may plan for: the rest is left to the loops it does not count
/// (a leap's inner loop, a tricubic or central-9 gradient's taps).
constexpr double plannedShare = 0.9;

std::string volumeName(const BindContext& context)
{
    return "'" + context.node.getName() + "'";
}

/// Loop iterations per view sample of the composition being bound (its implementations'
/// declared LoopCost: the march's own one, the lit shading's light loop, shadows, cones),
/// leaving out slot `except`'s.
double iterationsPerSample(const BindContext& context, const std::string& except = {})
{
    double perSample = 1.0, perLight = 0.0;
    for (const auto& [slot, name] : context.chosen)
        if (const ShaderFunction* f = ShaderFunctionRegistry::instance().find(slot, name); f && f->loops && slot != except) {
            const LoopCost cost = f->loops(context);
            perSample += cost.perSample;
            perLight += cost.perLight;
        }
    return perSample + double(context.lights.size()) * perLight;
}

}  // namespace

long loopIterationLimit()
{
    return graphicsDriver().find("llvmpipe") != std::string::npos ? 65535 : 0;
}

double viewSamplesPerRay(const BindContext& context)
{
    const osg::Vec3d box = context.boxSize.length2() > 0.0 ? context.boxSize : context.volume.worldSize();
    return std::ceil(box.length() / context.sampleDistance) + 1.0;
}

bool viewRayWithinLoopLimit(const BindContext& context)
{
    const long limit = loopIterationLimit();
    if (limit == 0 || !(context.sampleDistance > 0.0)) return true;
    return viewSamplesPerRay(context) * iterationsPerSample(context) <= plannedShare * double(limit);
}

void checkViewRayWithinLoopLimit(const BindContext& context)
{
    if (viewRayWithinLoopLimit(context)) return;
    const long limit = loopIterationLimit();
    const double samples = viewSamplesPerRay(context), perSample = iterationsPerSample(context);
    std::ostringstream why;
    why << "volume " << volumeName(context) << ": a ray through its box may take " << samples
        << " samples at a step of " << context.sampleDistance << " world units, " << perSample
        << " loop iterations each (its lights, shadows, cones), and this driver (" << graphicsDriver()
        << ") ends a pixel's loops after " << limit
        << " iterations, so the march would stop short: choose a lower samplerate (or a longer sampleDistance), "
           "fewer lights or cheaper shadows";
    throw std::runtime_error(why.str());
}

double shadowStepWithinLoopLimit(const BindContext& context, double step)
{
    const long limit = loopIterationLimit();
    if (limit == 0 || !(step > 0.0) || !(context.sampleDistance > 0.0)) return step;
    const osg::Vec3d box = context.boxSize.length2() > 0.0 ? context.boxSize : context.volume.worldSize();
    const double diagonal = box.length();
    const double view = viewSamplesPerRay(context);
    const double lights = double(std::max<std::size_t>(1, context.lights.size()));
    // Per view sample: what the rest of the composition loops (the march, the light loop), and
    // per light the shadow march's steps.
    const double rest = iterationsPerSample(context, "Shadowing");
    auto perPixel = [&](double shadowSteps) { return view * (rest + lights * shadowSteps); };
    const double budget = plannedShare * double(limit);
    const double wanted = std::min(maxShadowSteps, std::ceil(diagonal / step));
    if (perPixel(wanted) <= budget) return step;
    const double fitting = std::floor((budget / view - rest) / lights);
    if (fitting < 1.0) {
        std::ostringstream why;
        why << "Shadowing ray: volume " << volumeName(context) << ": " << view << " view samples per ray times "
            << lights << " light(s) take more than this driver's " << limit << " loop iterations per pixel ("
            << graphicsDriver() << ") with even one shadow step per sample: choose a lower samplerate or "
            << "another shadowing (light_volume, cone)";
        throw std::runtime_error(why.str());
    }
    const double lengthened = diagonal / fitting;
    static std::mutex told;
    static std::set<std::pair<std::string, double>> warned;
    const std::lock_guard<std::mutex> lock(told);
    if (warned.insert({context.node.getName(), lengthened}).second)
        OSG_WARN << "volren: volume " << volumeName(context) << ": shadow rays step " << lengthened
                 << " world units, not " << step << " (shadowStepFactor " << step / context.sampleDistance << " -> "
                 << lengthened / context.sampleDistance << "): " << view << " view samples per ray and "
                 << lights << " light(s) must stay within this driver's " << limit << " loop iterations per pixel"
                 << std::endl;
    return lengthened;
}

}  // namespace volren
