#include <volume_reference/ReferenceRenderer.h>

#include <glm/glm.hpp>

#include <osg/LightSource>

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

/// How a medium's samples are lit (the node's Shading and Illumination choices).
enum class Shading { None, Lighting, Threshold, Surface };
enum class Illumination { None, Lambert, BlinnPhong, CookTorrance };

/// The trilinear cell of a texture coordinate along each axis: the two voxel indices, their
/// weights, and d(weight of the upper voxel)/d(local unit) (0 where the field is clamped).
struct Cell
{
    int i[3][2];
    double w[3][2];
    double slope[3];

    Cell(const glm::dvec3& tc, const glm::ivec3& dims, const glm::dvec3& size)
    {
        for (int a = 0; a < 3; ++a) {
            const int n = dims[a];
            const double unclamped = tc[a] * n - 0.5;
            const double x = std::clamp(unclamped, 0.0, double(n - 1));
            const int i0 = std::min(int(std::floor(x)), std::max(n - 2, 0));
            const double f = n > 1 ? x - i0 : 0.0;
            i[a][0] = i0;
            i[a][1] = std::min(i0 + 1, n - 1);
            w[a][0] = 1.0 - f;
            w[a][1] = f;
            slope[a] = (n > 1 && unclamped == x) ? n / size[a] : 0.0;
        }
    }
    double weight(int dx, int dy, int dz) const { return w[0][dx] * w[1][dy] * w[2][dz]; }
};

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
    Shading shading = Shading::None;
    Illumination illumination = Illumination::None;
    double ambient = 0.0, specular = 0.0, shininess = 1.0, roughness = 1.0, shadingThreshold = 0.0;
    /// Lights in the node's local coordinates: position (w = 0: direction towards the light) and colour.
    std::vector<std::pair<glm::dvec4, glm::dvec3>> lights;
    ReferenceOptions::Gradient gradientKind = ReferenceOptions::Gradient::Exact;

    /// Trilinear interpolation of the grid's central differences (per local unit) at `tc`.
    glm::dvec3 centralDifferences(const glm::dvec3& tc) const
    {
        const Cell cell(tc, dims, size);
        auto at = [&](int x, int y, int z) {
            return volume->value(std::clamp(x, 0, dims.x - 1), std::clamp(y, 0, dims.y - 1), std::clamp(z, 0, dims.z - 1));
        };
        glm::dvec3 g(0.0);
        for (int dz = 0; dz < 2; ++dz)
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const double weight = cell.weight(dx, dy, dz);
                    if (weight == 0.0) continue;
                    const int x = cell.i[0][dx], y = cell.i[1][dy], z = cell.i[2][dz];
                    g += weight * glm::dvec3(at(x + 1, y, z) - at(x - 1, y, z), at(x, y + 1, z) - at(x, y - 1, z),
                                             at(x, y, z + 1) - at(x, y, z - 1));
                }
        return g * 0.5 * glm::dvec3(dims) / size;  // per voxel -> per local unit
    }

    /// Trilinear data value at texture coordinate `tc` ([0,1]^3; voxel centres at (i+0.5)/n),
    /// and, when `gradient` is given, its exact gradient per local (world) unit; zero along an
    /// axis where the field is clamped (outside the outermost voxel centres).
    double value(const glm::dvec3& tc, glm::dvec3* gradient = nullptr) const
    {
        const Cell c(tc, dims, size);
        double sum = 0.0;
        glm::dvec3 g(0.0);
        for (int dz = 0; dz < 2; ++dz)
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const double weight = c.weight(dx, dy, dz);
                    if (weight == 0.0 && !gradient) continue;
                    const double v = volume->value(c.i[0][dx], c.i[1][dy], c.i[2][dz]);
                    sum += weight * v;
                    if (gradient) {  // d weight / d local along each axis: +-slope times the other two
                        const double sx = dx ? c.slope[0] : -c.slope[0], sy = dy ? c.slope[1] : -c.slope[1],
                                     sz = dz ? c.slope[2] : -c.slope[2];
                        g += v * glm::dvec3(sx * c.w[1][dy] * c.w[2][dz], c.w[0][dx] * sy * c.w[2][dz],
                                            c.w[0][dx] * c.w[1][dy] * sz);
                    }
                }
        if (gradient) *gradient = g;
        return sum;
    }

    /// Emitted colour of a sample of TF colour `albedo` and opacity `alpha` at `tc` (local point
    /// `local`), seen along `view` (unit, towards the eye, local axes).
    glm::dvec3 shade(const glm::dvec3& tc, const glm::dvec3& local, const glm::dvec3& view, const glm::dvec3& albedo,
                     double alpha) const
    {
        if (shading == Shading::None || (shading == Shading::Threshold && alpha < shadingThreshold)) return albedo;
        glm::dvec3 gradient;
        if (gradientKind == ReferenceOptions::Gradient::CentralDifferences) gradient = centralDifferences(tc);
        else value(tc, &gradient);
        const double scale = std::max({std::abs(gradient.x), std::abs(gradient.y), std::abs(gradient.z)});
        glm::dvec3 normal = scale > 0.0 && std::isfinite(scale) ? -glm::normalize(gradient / scale) : view;
        if (glm::dot(normal, view) < 0.0) normal = -normal;  // two-sided: normals face the viewer
        glm::dvec3 colour = ambient * albedo;
        for (const auto& [position, lightColour] : lights) {
            const glm::dvec3 toLight = position.w == 0.0 ? glm::dvec3(position) : glm::dvec3(position) - local;
            const double length = glm::length(toLight);
            if (!(length > 0.0)) continue;
            colour += lightColour * illuminate(normal, view, toLight / length, albedo);
        }
        if (shading != Shading::Surface) return colour;
        // lighting_surface: lit by w = 1 - exp(-|g| / (0.05 G)), G = the TF window per smallest spacing.
        const double surfaceGradient = 0.05 * (domainMax - domainMin) / unitLength;
        double w = surfaceGradient > 0.0 ? -std::expm1(-glm::length(gradient) / surfaceGradient) : 1.0;
        if (!(w >= 0.0)) w = 1.0;  // a non-finite gradient: lit, as its normal is
        return albedo + w * (colour - albedo);
    }

    /// Light reflected towards `v` from a unit light from `l` by a surface of normal `n`.
    glm::dvec3 illuminate(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& albedo) const
    {
        const double nl = glm::dot(n, l);
        switch (illumination) {
        case Illumination::None: return glm::dvec3(0.0);
        case Illumination::Lambert: return albedo * std::max(nl, 0.0);
        case Illumination::BlinnPhong: {
            if (!(nl > 0.0)) return glm::dvec3(0.0);
            const glm::dvec3 halfway = l + v;
            const double h = glm::length(halfway);
            const double highlight = h > 1e-12 ? std::pow(std::max(glm::dot(n, halfway / h), 0.0), shininess) : 0.0;
            return albedo * nl + glm::dvec3(specular * highlight);
        }
        case Illumination::CookTorrance: {
            // GGX distribution, Smith-Schlick geometry (k = a/2), Schlick Fresnel with F0 = 0.04.
            if (!(nl > 0.0)) return glm::dvec3(0.0);
            const double nv = std::max(glm::dot(n, v), 1e-4);
            const glm::dvec3 halfway = l + v;
            const double len = glm::length(halfway);
            const glm::dvec3 h = len > 1e-12 ? halfway / len : n;
            const double nh = std::max(glm::dot(n, h), 0.0), vh = std::max(glm::dot(v, h), 0.0);
            const double a = std::max(roughness * roughness, 1e-4), a2 = a * a;
            const double d = nh * nh * (a2 - 1.0) + 1.0;
            const double distribution = a2 / (M_PI * d * d);
            const double k = a * 0.5;
            const double geometry = (nl / (nl * (1.0 - k) + k)) * (nv / (nv * (1.0 - k) + k));
            const double fresnel = 0.04 + 0.96 * std::pow(1.0 - vh, 5.0);
            return albedo * nl + glm::dvec3(specular * distribution * geometry * fresnel / (4.0 * nl * nv) * nl);
        }
        }
        return glm::dvec3(0.0);
    }
};

/// The implementation of `slot` for a volume: the renderer's choice when given, else the node's
/// own (forced null, chosen, or null when unset).
std::string choiceOf(const ReferenceScene::Placed& placed, const RenderSettings& s, const std::string& slot)
{
    if (auto it = placed.choice.find(slot); it != placed.choice.end()) return it->second;
    if (s.forceNull.count(slot)) return "null";
    auto it = s.functions.find(slot);
    return it == s.functions.end() ? "null" : it->second;
}

/// Sets how `m` is lit from the volume's choices (the renderer's, or the node's own when lights
/// reach it: `lit`).
void setShading(Medium& m, const ReferenceScene::Placed& placed, bool lit)
{
    const auto& node = static_cast<const VolumeNode&>(*placed.node);
    const RenderSettings& s = node.settings;
    const bool decided = !placed.choice.empty();
    const std::string illumination = decided || lit ? choiceOf(placed, s, "Illumination") : "null";
    const std::string shading = decided || lit ? choiceOf(placed, s, "Shading") : "null";
    if (shading == "null") m.shading = Shading::None;
    else if (shading == "lighting") m.shading = Shading::Lighting;
    else if (shading == "lighting_threshold") m.shading = Shading::Threshold;
    else if (shading == "lighting_surface") m.shading = Shading::Surface;
    else throw std::invalid_argument("reference: no model for Shading '" + shading + "' (volume '" + node.getName() + "')");
    if (illumination == "null") m.illumination = Illumination::None;
    else if (illumination == "lambert") m.illumination = Illumination::Lambert;
    else if (illumination == "blinn_phong") m.illumination = Illumination::BlinnPhong;
    else if (illumination == "cook_torrance") m.illumination = Illumination::CookTorrance;
    else
        throw std::invalid_argument("reference: no model for Illumination '" + illumination + "' (volume '" +
                                    node.getName() + "')");
    m.ambient = s.ambient;
    m.specular = s.specular;
    m.shininess = s.shininess;
    m.roughness = s.roughness;
    m.shadingThreshold = s.shadingThreshold;
}

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
    Integrator(const ReferenceScene& scene, const ReferenceCamera& camera, const ReferenceOptions& options)
        : _options(options)
    {
        _unit = std::numeric_limits<double>::infinity();
        const std::size_t lightCount = options.lighting ? std::min<std::size_t>(scene.lights.size(), 8) : 0;
        const osg::Matrixd eyeToWorld = osg::Matrixd::inverse(camera.view);
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
            setShading(m, placed, lightCount > 0);
            m.gradientKind = options.gradient;
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
                const osg::Vec3d localPoint = osg::Vec3d(p.x, p.y, p.z) * m.worldToLocal;
                const glm::dvec3 local = toGlm(localPoint);
                const glm::dvec3 tc = local / m.size + 0.5;
                if (tc.x < 0 || tc.y < 0 || tc.z < 0 || tc.x > 1 || tc.y > 1 || tc.z > 1) continue;
                const double v = m.value(tc);
                if (std::isnan(v)) continue;  // NaN voxels are empty
                const osg::Vec4 rgba = m.tf->evaluate(std::clamp(v, m.domainMin, m.domainMax));
                const double alpha = rgba.a();
                if (alpha <= 0.0) continue;
                glm::dvec3 c(rgba.r(), rgba.g(), rgba.b());
                if (m.shading != Shading::None) {
                    const glm::dvec3 view =
                        -glm::normalize(toGlm(osg::Matrixd::transform3x3(osg::Vec3d(ray.direction.x, ray.direction.y,
                                                                                     ray.direction.z),
                                                                          m.worldToLocal)));
                    c = m.shade(tc, local, view, c, alpha);
                }
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
    const Integrator integrator(scene, camera, options);
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
