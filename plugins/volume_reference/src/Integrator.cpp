// The reference's integrator: per ray, front to back through the union of the media's boxes,
// media adding along the ray, halving the step until two results agree within the tolerance
// (the shadow rays of its lit samples converging on their own: Shadows.cpp).
#include "Integrator.h"

#include <osg/BoundingBox>
#include <osg/LightSource>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace volren::reference {

namespace {

/// The medium of `placed`, lit by the scene's first `lightCount` lights (eye-fixed ones placed
/// by the camera: `eyeToWorld`), clipped by `clips` (from world coordinates) for its shadows.
Medium mediumOf(const ReferenceScene& scene, const ReferenceScene::Placed& placed, std::size_t lightCount,
                const osg::Matrixd& eyeToWorld, const std::vector<Clip>& clips, const ReferenceOptions& options)
{
    const auto& node = static_cast<const VolumeNode&>(*placed.node);
    Medium m;
    m.volume = node.getVolume();
    m.tf = node.getTransferFunction();
    m.localToWorld = placed.localToWorld;
    m.worldToLocal = osg::Matrixd::inverse(placed.localToWorld);
    m.size = toGlm(m.volume->worldSize());
    const osg::Vec3i& d = m.volume->dims();
    m.dims = {d.x(), d.y(), d.z()};
    m.unitLength = m.volume->minSpacing();
    m.domainMin = m.tf->domainMin();
    m.domainMax = m.tf->domainMax();
    setShading(m, placed, lightCount > 0);
    setWeighting(m, placed);
    m.gradientKind = options.gradient;
    // Shadow rays converge like view rays, to a quarter of the tolerance (a transmittance
    // scales a light's whole term), through every clip shape (all apply to every volume).
    m.shadowTolerance = options.tolerance / 4.0;
    m.shadowFirstStep = options.firstStep;
    m.shadowFinestStep = options.finestStep;
    m.occlusionDirections = std::max(1, options.occlusionDirections);
    m.occlusionStep = options.occlusionStep;
    m.shadowsGeometry = placed.shadowsGeometry && lightCount > 0 && m.shading != Shading::None;
    if ((m.shadows != ReferenceScene::Shadows::None || m.shadowsGeometry) && lightCount > 0 && m.shading != Shading::None) {
        for (const Clip& c : clips) m.clips.push_back({c.node, m.localToWorld * c.toShape});
        m.findEmptyBlocks();
        if (scene.occluders) m.occluders = &scene;
    }
    for (std::size_t i = 0; i < lightCount; ++i) {
        const auto& source = static_cast<const osg::LightSource&>(*scene.lights[i].node);
        const osg::Matrixd toLocal =
            (source.getReferenceFrame() == osg::LightSource::ABSOLUTE_RF ? eyeToWorld : scene.lights[i].localToWorld) *
            m.worldToLocal;
        const osg::Vec4d p = source.getLight()->getPosition();
        glm::dvec4 position;
        if (p.w() == 0.0) {
            osg::Vec3d d = osg::Matrixd::transform3x3(osg::Vec3d(p.x(), p.y(), p.z()), toLocal);
            d.normalize();
            position = glm::dvec4(toGlm(d), 0.0);
        } else {
            position = glm::dvec4(toGlm(osg::Vec3d(p.x(), p.y(), p.z()) / p.w() * toLocal), 1.0);
        }
        const osg::Vec4 c = source.getLight()->getDiffuse();
        m.lights.emplace_back(position, glm::dvec3(c.r(), c.g(), c.b()));
    }
    return m;
}

}  // namespace

Integrator::Integrator(const ReferenceScene& scene, const ReferenceCamera& camera, const ReferenceOptions& options)
    : _options(options)
{
    _unit = std::numeric_limits<double>::infinity();
    const std::size_t lightCount = options.lighting ? std::min<std::size_t>(scene.lights.size(), 8) : 0;
    const osg::Matrixd eyeToWorld = osg::Matrixd::inverse(camera.view);
    for (const auto& placed : scene.clips)
        _clips.push_back({static_cast<const ClipNode*>(placed.node.get()), osg::Matrixd::inverse(placed.localToWorld)});
    for (const auto& placed : scene.volumes) {
        Medium m = mediumOf(scene, placed, lightCount, eyeToWorld, _clips, options);
        _unit = std::min(_unit, m.unitLength);
        _media.push_back(m);
    }
    groupMedia(scene);
}

void Integrator::groupMedia(const ReferenceScene& scene)
{
    // Where every medium combines its media, one group: non-overlapping media integrated together
    // are the same as composited in ray order. Otherwise the renderer's ray groups: boxes (world
    // bounds of their corners) that overlap, transitively.
    const std::size_t n = _media.size();
    const bool media = std::all_of(scene.volumes.begin(), scene.volumes.end(), [](const ReferenceScene::Placed& p) {
        return p.blending == ReferenceScene::Blending::Media;
    });
    if (media) {
        Group all;
        for (std::size_t i = 0; i < n; ++i) all.members.push_back(i);
        _groups = {all};
        return;
    }
    std::vector<osg::BoundingBoxd> bounds(n);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 8; ++c) {
            const osg::Vec3d corner((c & 1 ? 0.5 : -0.5) * _media[i].size.x, (c & 2 ? 0.5 : -0.5) * _media[i].size.y,
                                    (c & 4 ? 0.5 : -0.5) * _media[i].size.z);
            bounds[i].expandBy(corner * _media[i].localToWorld);
        }
    std::vector<std::size_t> root(n);
    for (std::size_t i = 0; i < n; ++i) root[i] = i;
    auto find = [&root](std::size_t i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            bool overlap = true;
            for (int a = 0; a < 3; ++a)
                overlap = overlap && bounds[i]._min[a] < bounds[j]._max[a] && bounds[j]._min[a] < bounds[i]._max[a];
            if (overlap) root[find(j)] = find(i);
        }
    std::map<std::size_t, std::size_t> index;
    for (std::size_t i = 0; i < n; ++i) {
        auto [it, added] = index.emplace(find(i), _groups.size());
        if (added) _groups.push_back({{}, scene.volumes[i].blending});  // the first member's
        _groups[it->second].members.push_back(i);
    }
}

glm::dvec4 Integrator::integrate(const Ray& ray, double end, bool& converged, bool& shadowsConverged,
                                 double& finest) const
{
    double u0 = 1.0, u1 = 0.0;  // the union of the boxes along the ray, as fractions of it
    for (const Medium& m : _media) {
        double a = 0.0, b = 1.0;
        if (boxSpan(m, ray, a, b)) u0 = std::min(u0, a), u1 = std::max(u1, b);
    }
    u1 = std::min(u1, end);
    converged = shadowsConverged = true;
    if (!(u1 > u0)) return glm::dvec4(0.0);
    double step = _options.firstStep * _unit;
    ShadowTally discarded;
    glm::dvec4 coarse = sample(ray, u0, u1, step, discarded);
    for (;;) {
        step *= 0.5;
        ShadowTally tally;  // of the march that may be kept
        const glm::dvec4 fine = sample(ray, u0, u1, step, tally);
        double change = 0.0;
        for (int c = 0; c < 4; ++c) change = std::max(change, std::abs(fine[c] - coarse[c]));
        finest = std::min({finest, step, tally.finest});
        shadowsConverged = tally.converged;
        if (change <= _options.tolerance) return fine;
        if (step <= _options.finestStep * _unit) {
            converged = false;
            return fine;
        }
        coarse = fine;
    }
}

double Integrator::lightOnGeometry(const glm::dvec3& world, ShadowTally& tally) const
{
    double light = 1.0;
    for (const Medium& m : _media)
        if (m.shadowsGeometry)
            light *= m.lightOnGeometry(toGlm(osg::Vec3d(world.x, world.y, world.z) * m.worldToLocal), tally);
    return light;
}

bool Integrator::boxSpan(const Medium& m, const Ray& ray, double& a, double& b)
{
    const osg::Vec3d o = osg::Vec3d(ray.origin.x, ray.origin.y, ray.origin.z) * m.worldToLocal;
    const osg::Vec3d e = osg::Vec3d(ray.origin.x + ray.direction.x, ray.origin.y + ray.direction.y,
                                    ray.origin.z + ray.direction.z) * m.worldToLocal;
    const osg::Vec3d d = e - o;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = -0.5 * m.size[axis], hi = 0.5 * m.size[axis];
        if (d[axis] == 0.0) {
            if (o[axis] < lo || o[axis] > hi) return false;
            continue;
        }
        double t0 = (lo - o[axis]) / d[axis], t1 = (hi - o[axis]) / d[axis];
        if (t0 > t1) std::swap(t0, t1);
        a = std::max(a, t0);
        b = std::min(b, t1);
    }
    return b > a;
}

glm::dvec4 Integrator::sample(const Ray& ray, double u0, double u1, double step, ShadowTally& tally) const
{
    if (_groups.size() == 1 && _groups.front().blending == ReferenceScene::Blending::Media)
        return march(ray, u0, u1, step, tally);
    // Each group's image, in the order the ray enters the groups, composited front to back.
    std::vector<std::pair<double, const Group*>> order;
    for (const Group& g : _groups) {
        double enter = 2.0;
        for (std::size_t k : g.members)
            if (double a = 0.0, b = 1.0; boxSpan(_media[k], ray, a, b)) enter = std::min(enter, a);
        if (enter <= 1.0) order.emplace_back(enter, &g);
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    glm::dvec4 out(0.0);
    for (const auto& [enter, g] : order) {
        glm::dvec4 image(0.0);
        if (g->blending == ReferenceScene::Blending::Media) {
            image = march(ray, u0, u1, step, tally, &g->members);
        } else {
            glm::dvec3 colour(0.0);
            double clear = 1.0;  // prod(1 - alpha)
            for (std::size_t k : g->members) {
                const std::vector<std::size_t> alone{k};
                const glm::dvec4 one = g->blending == ReferenceScene::Blending::Images ? march(ray, u0, u1, step, tally, &alone)
                                                                                        : maximum(ray, u0, u1, step, k);
                colour += glm::dvec3(one);
                clear *= 1.0 - one.a;
            }
            image = glm::dvec4(glm::min(colour, glm::dvec3(1.0)), 1.0 - clear);
        }
        out += (1.0 - out.a) * image;
    }
    return out;
}

glm::dvec4 Integrator::maximum(const Ray& ray, double u0, double u1, double step, std::size_t index) const
{
    const Medium& m = _media[index];
    const double start = u0 * ray.length, end = u1 * ray.length;
    const auto count = std::size_t(std::ceil((end - start) / step));
    const double h = (end - start) / double(count);
    bool found = false;
    double best = 0.0, bestWeight = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
        const glm::dvec3 p = ray.origin + ray.direction * ((start + (double(k) + 0.5) * h) / ray.length);
        const glm::dvec3 tc = toGlm(osg::Vec3d(p.x, p.y, p.z) * m.worldToLocal) / m.size + 0.5;
        if (tc.x < 0 || tc.y < 0 || tc.z < 0 || tc.x > 1 || tc.y > 1 || tc.z > 1 || !kept(p)) continue;
        const double w = m.weighting(tc.x, tc.y, tc.z);
        if (!(w > 0.0)) continue;  // weighted out, as clipped
        const double v = m.value(tc);
        if (std::isnan(v)) continue;
        if (found && v == best) bestWeight = std::max(bestWeight, w);  // a tie shows as its most weighted sample
        if (found && !(v > best)) continue;
        best = v;
        bestWeight = w;
        found = true;
    }
    if (!found) return glm::dvec4(0.0);
    const osg::Vec4 c = m.tf->evaluate(std::clamp(best, m.domainMin, m.domainMax));
    const double a = c.a() * bestWeight;  // the opacity scaled by the weighting where the maximum lies
    return glm::dvec4(c.r() * a, c.g() * a, c.b() * a, a);
}

glm::dvec4 Integrator::march(const Ray& ray, double u0, double u1, double step, ShadowTally& tally,
                             const std::vector<std::size_t>* members) const
{
    const double start = u0 * ray.length, end = u1 * ray.length;
    const auto count = std::size_t(std::ceil((end - start) / step));
    const double h = (end - start) / double(count);  // equal steps that end exactly at the exit
    glm::dvec3 colour(0.0);
    double transmittance = 1.0;
    for (std::size_t k = 0; k < count && transmittance > 0.0; ++k) {
        const double s = start + (double(k) + 0.5) * h;
        const glm::dvec3 p = ray.origin + ray.direction * (s / ray.length);
        double extinction = 0.0;  // sum over the media
        glm::dvec3 emission(0.0);  // sum of extinction x colour
        bool opaque = false;
        glm::dvec3 opaqueColour(0.0);
        if (!kept(p)) continue;
        for (std::size_t index = 0; index < _media.size(); ++index) {
            if (members && std::find(members->begin(), members->end(), index) == members->end()) continue;
            const Medium& m = _media[index];
            const osg::Vec3d localPoint = osg::Vec3d(p.x, p.y, p.z) * m.worldToLocal;
            const glm::dvec3 local = toGlm(localPoint);
            const glm::dvec3 tc = local / m.size + 0.5;
            if (tc.x < 0 || tc.y < 0 || tc.z < 0 || tc.x > 1 || tc.y > 1 || tc.z > 1) continue;
            osg::Vec4 rgba;
            if (!m.classify(tc, rgba)) continue;  // NaN or transparent: empty
            const double alpha = rgba.a();
            glm::dvec3 c(rgba.r(), rgba.g(), rgba.b());
            if (m.shading != Shading::None) {
                const glm::dvec3 view =
                    -glm::normalize(toGlm(osg::Matrixd::transform3x3(osg::Vec3d(ray.direction.x, ray.direction.y,
                                                                                 ray.direction.z),
                                                                      m.worldToLocal)));
                c = m.shade(tc, local, view, c, alpha, tally);
            }
            if (alpha >= 1.0) {  // infinite extinction: opaque at this point
                opaque = true;
                opaqueColour = c;
                continue;
            }
            const double sigma = m.extinction(alpha);
            extinction += sigma;
            emission += sigma * c;
        }
        if (opaque) {
            colour += transmittance * opaqueColour;
            transmittance = 0.0;
            break;
        }
        if (extinction <= 0.0) continue;
        const double a = -std::expm1(-extinction * h);  // 1 - exp(-σh), exact for small σh too
        colour += transmittance * a * (emission / extinction);
        transmittance *= 1.0 - a;
    }
    return glm::dvec4(colour, 1.0 - transmittance);
}

bool Integrator::kept(const glm::dvec3& p) const
{
    for (const Clip& c : _clips)
        if (!c.node->keeps(osg::Vec3d(p.x, p.y, p.z) * c.toShape)) return false;
    return true;
}

}  // namespace volren::reference
