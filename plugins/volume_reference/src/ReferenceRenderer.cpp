#include <volume_reference/ReferenceRenderer.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace volren {

namespace {

glm::dvec3 toGlm(const osg::Vec3d& v) { return {v.x(), v.y(), v.z()}; }

/// One volume as the integrator needs it.
struct Medium
{
    const Volume* volume = nullptr;
    const TransferFunction* tf = nullptr;
    osg::Matrixd worldToLocal;
    glm::dvec3 size;       ///< box size (world units of the node's frame)
    glm::ivec3 dims;
    double unitLength = 1.0;  ///< Δ0: the smallest voxel spacing; TF alpha is per this length
    double domainMin = 0.0, domainMax = 1.0;

    /// Trilinear data value at texture coordinate `tc` ([0,1]^3; voxel centres at (i+0.5)/n).
    double value(const glm::dvec3& tc) const
    {
        double w[3][2];
        int i[3][2];
        for (int a = 0; a < 3; ++a) {
            const int n = dims[a];
            const double x = std::clamp(tc[a] * n - 0.5, 0.0, double(n - 1));
            const int i0 = std::min(int(std::floor(x)), std::max(n - 2, 0));
            const double f = n > 1 ? x - i0 : 0.0;
            i[a][0] = i0;
            i[a][1] = std::min(i0 + 1, n - 1);
            w[a][0] = 1.0 - f;
            w[a][1] = f;
        }
        double sum = 0.0;
        for (int dz = 0; dz < 2; ++dz)
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const double weight = w[0][dx] * w[1][dy] * w[2][dz];
                    if (weight == 0.0) continue;
                    sum += weight * volume->value(i[0][dx], i[1][dy], i[2][dz]);
                }
        return sum;
    }
};

struct Clip
{
    const ClipNode* node;
    osg::Matrixd worldToLocal;
};

/// The ray of one pixel in world space, from the near to the far plane.
struct Ray
{
    glm::dvec3 origin, direction;  ///< point at the near plane; far - near
    double length = 0.0;           ///< |far - near| in world units
};

class Integrator
{
public:
    Integrator(const ReferenceScene& scene, const ReferenceOptions& options) : _options(options)
    {
        _unit = std::numeric_limits<double>::infinity();
        for (const auto& placed : scene.volumes) {
            const auto& node = static_cast<const VolumeNode&>(*placed.node);
            Medium m;
            m.volume = node.getVolume();
            m.tf = node.getTransferFunction();
            m.worldToLocal = osg::Matrixd::inverse(placed.localToWorld);
            m.size = toGlm(m.volume->worldSize());
            const osg::Vec3i& d = m.volume->dims();
            m.dims = {d.x(), d.y(), d.z()};
            m.unitLength = m.volume->minSpacing();
            m.domainMin = m.tf->domainMin();
            m.domainMax = m.tf->domainMax();
            _unit = std::min(_unit, m.unitLength);
            _media.push_back(m);
        }
        for (const auto& placed : scene.clips)
            _clips.push_back({static_cast<const ClipNode*>(placed.node.get()), osg::Matrixd::inverse(placed.localToWorld)});
    }

    /// Premultiplied RGBA of one ray (before the background) up to the fraction `end` of it,
    /// converged as the options say.
    glm::dvec4 integrate(const Ray& ray, double end, bool& converged, double& finest) const
    {
        double u0 = 1.0, u1 = 0.0;  // the union of the boxes along the ray, as fractions of it
        for (const Medium& m : _media) {
            double a = 0.0, b = 1.0;
            if (boxSpan(m, ray, a, b)) u0 = std::min(u0, a), u1 = std::max(u1, b);
        }
        u1 = std::min(u1, end);
        converged = true;
        if (!(u1 > u0)) return glm::dvec4(0.0);
        double step = _options.firstStep * _unit;
        glm::dvec4 coarse = march(ray, u0, u1, step);
        for (;;) {
            step *= 0.5;
            const glm::dvec4 fine = march(ray, u0, u1, step);
            double change = 0.0;
            for (int c = 0; c < 4; ++c) change = std::max(change, std::abs(fine[c] - coarse[c]));
            finest = std::min(finest, step);
            if (change <= _options.tolerance) return fine;
            if (step <= _options.finestStep * _unit) {
                converged = false;
                return fine;
            }
            coarse = fine;
        }
    }

private:
    /// Where the ray is inside the box of `m`, as fractions [a, b] of the ray; false if nowhere.
    static bool boxSpan(const Medium& m, const Ray& ray, double& a, double& b)
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

    /// Front-to-back over [u0, u1] of the ray with `step` world units, sampled at step midpoints.
    glm::dvec4 march(const Ray& ray, double u0, double u1, double step) const
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
            for (const Medium& m : _media) {
                const osg::Vec3d local = osg::Vec3d(p.x, p.y, p.z) * m.worldToLocal;
                const glm::dvec3 tc = glm::dvec3(local.x(), local.y(), local.z()) / m.size + 0.5;
                if (tc.x < 0 || tc.y < 0 || tc.z < 0 || tc.x > 1 || tc.y > 1 || tc.z > 1) continue;
                const double v = m.value(tc);
                if (std::isnan(v)) continue;  // NaN voxels are empty
                const osg::Vec4 rgba = m.tf->evaluate(std::clamp(v, m.domainMin, m.domainMax));
                const double alpha = rgba.a();
                if (alpha <= 0.0) continue;
                const glm::dvec3 c(rgba.r(), rgba.g(), rgba.b());
                if (alpha >= 1.0) {  // infinite extinction: opaque at this point
                    opaque = true;
                    opaqueColour = c;
                    continue;
                }
                const double sigma = -std::log1p(-alpha) / m.unitLength;
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

    bool kept(const glm::dvec3& p) const
    {
        for (const Clip& c : _clips)
            if (!c.node->keeps(osg::Vec3d(p.x, p.y, p.z) * c.worldToLocal)) return false;
        return true;
    }

    ReferenceOptions _options;
    std::vector<Medium> _media;
    std::vector<Clip> _clips;
    double _unit = 1.0;
};

}  // namespace

ReferenceImage renderReference(const ReferenceScene& scene, const ReferenceCamera& camera, const ReferenceOptions& options)
{
    ReferenceImage image;
    image.width = camera.width;
    image.height = camera.height;
    image.rgba.assign(std::size_t(camera.width) * camera.height * 4, 0.0);
    const Integrator integrator(scene, options);
    const osg::Matrixd clipToWorld = osg::Matrixd::inverse(camera.view * camera.projection);

    const std::size_t pixels = std::size_t(camera.width) * camera.height;
    const bool withGeometry = !options.geometryDepth.empty();
    if (withGeometry && (options.geometryDepth.size() != pixels || options.geometryColour.size() != pixels * 4))
        throw std::invalid_argument("reference: geometry depth and colour must have one value (four) per pixel");
    std::atomic<int> nextRow{0};
    std::atomic<std::size_t> unconverged{0};
    double finest = std::numeric_limits<double>::infinity();
    std::mutex finestMutex;
    auto work = [&] {
        double localFinest = std::numeric_limits<double>::infinity();
        for (int y; (y = nextRow++) < camera.height;) {
            for (int x = 0; x < camera.width; ++x) {
                const double nx = 2.0 * (x + 0.5) / camera.width - 1.0, ny = 2.0 * (y + 0.5) / camera.height - 1.0;
                const osg::Vec3d nearPoint = osg::Vec3d(nx, ny, -1.0) * clipToWorld;
                const osg::Vec3d farPoint = osg::Vec3d(nx, ny, 1.0) * clipToWorld;
                Ray ray;
                ray.origin = toGlm(nearPoint);
                ray.direction = toGlm(farPoint - nearPoint);
                ray.length = glm::length(ray.direction);
                const std::size_t pixel = std::size_t(y) * camera.width + x;
                // Opaque geometry ends the ray at its depth and lies behind the volumes.
                double end = 1.0;
                glm::dvec4 behind(toGlm(options.background), 0.0);
                if (withGeometry && options.geometryDepth[pixel] < 1.0f) {
                    const osg::Vec3d hit = osg::Vec3d(nx, ny, 2.0 * options.geometryDepth[pixel] - 1.0) * clipToWorld;
                    end = glm::length(toGlm(hit - nearPoint)) / ray.length;
                }
                if (withGeometry)
                    for (int k = 0; k < 4; ++k) behind[k] = options.geometryColour[pixel * 4 + k];
                bool converged = true;
                const glm::dvec4 c = integrator.integrate(ray, end, converged, localFinest);
                if (!converged) ++unconverged;
                double* out = &image.rgba[pixel * 4];
                for (int k = 0; k < 4; ++k) out[k] = c[k] + (1.0 - c.a) * behind[k];
            }
        }
        std::lock_guard<std::mutex> lock(finestMutex);
        finest = std::min(finest, localFinest);
    };
    unsigned int threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> pool;
    for (unsigned int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    image.unconverged = unconverged;
    image.finestStepUsed = std::isfinite(finest) ? finest : 0.0;
    return image;
}

}  // namespace volren
