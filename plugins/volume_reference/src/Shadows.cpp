// The reference's shadows: the transmittance from a sample to a light through the sample's own
// medium (its clip shapes removing material as for the view ray), halving the step until two
// results agree within the tolerance. Blocks the TF leaves empty are passed over unsampled.
#include "Medium.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace volren::reference {

namespace {

constexpr int blockCells = 4;  ///< edge of an empty-space block, in trilinear cells

/// The trilinear cell's lower voxel index along an axis of `n` voxels (as Cell's).
int lowerVoxel(double tc, int n)
{
    const double x = std::clamp(tc * n - 0.5, 0.0, double(n - 1));
    return std::min(int(std::floor(x)), std::max(n - 2, 0));
}

/// Largest TF opacity over the data values [lo, hi]: at their ends or at a control point between
/// (segments are monotone: linear, or monotone cubic).
double largestOpacity(const TransferFunction& tf, double lo, double hi)
{
    lo = std::clamp(lo, tf.domainMin(), tf.domainMax());
    hi = std::clamp(hi, tf.domainMin(), tf.domainMax());
    double largest = std::max(tf.evaluate(lo).a(), tf.evaluate(hi).a());
    for (auto it = tf.points().upper_bound(lo); it != tf.points().end() && it->first < hi; ++it)
        largest = std::max(largest, double(it->second.a()));
    return largest;
}

/// Optical depth (in local lengths) of [0, length] from `local` along `l`, in `count` equal steps
/// sampled at their midpoints; infinite at an opaque sample. Stops past `enough`.
double opticalDepth(const Medium& m, const glm::dvec3& local, const glm::dvec3& l, double length, std::size_t count,
                    double enough)
{
    const double h = length / double(count);
    double depth = 0.0;
    for (std::size_t k = 0; k < count && depth <= enough; ++k) {
        const glm::dvec3 p = local + l * ((double(k) + 0.5) * h);
        const glm::dvec3 tc = p / m.size + 0.5;
        if (tc.x < 0.0 || tc.y < 0.0 || tc.z < 0.0 || tc.x > 1.0 || tc.y > 1.0 || tc.z > 1.0) continue;  // empty outside
        if (m.inEmptyBlock(tc)) continue;
        bool kept = true;
        for (const Clip& c : m.clips)
            if (!c.node->keeps(osg::Vec3d(p.x, p.y, p.z) * c.toShape)) {
                kept = false;
                break;
            }
        osg::Vec4 rgba;
        if (!kept || !m.classify(tc, rgba) || !(rgba.a() > 0.0)) continue;
        if (rgba.a() >= 1.0) return std::numeric_limits<double>::infinity();
        depth += m.extinction(rgba.a()) * h;
    }
    return depth;
}

}  // namespace

double Medium::ambientOcclusion(const glm::dvec3& local, const glm::dvec3& normal, ShadowTally&) const
{
    const double reach = occlusionDistance - occlusionStart;
    if (!(reach > 0.0)) return 1.0;
    if (!(occlusionStep > 0.0)) throw std::invalid_argument("reference: ambient occlusion step must be > 0");
    // Cosine-weighted directions at the midpoints of n x n strata of the unit square (r = sqrt(u),
    // phi = 2 pi v over the disc, lifted onto the hemisphere): their mean transmittance is the
    // cosine-weighted integral over pi. Every direction takes the same steps: outside the box
    // the medium is empty, so a path cut by a face needs no step count of its own (which would
    // jump with the position).
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 u = glm::normalize(glm::cross(normal, helper)), v = glm::cross(normal, u);
    const std::size_t steps = std::max<std::size_t>(1, std::size_t(std::ceil(reach / (occlusionStep * unitLength))));
    const int n = occlusionDirections;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double a = (i + 0.5) / n, phi = 2.0 * M_PI * (j + 0.5) / n, r = std::sqrt(a);
            const glm::dvec3 d = u * (r * std::cos(phi)) + v * (r * std::sin(phi)) + normal * std::sqrt(1.0 - a);
            const double worldPerLocal = osg::Matrixd::transform3x3(osg::Vec3d(d.x, d.y, d.z), localToWorld).length();
            const double enough = 40.0 / worldPerLocal;  // T < 4.3e-18
            sum += std::exp(-opticalDepth(*this, local + d * occlusionStart, d, reach, steps, enough) * worldPerLocal);
        }
    return sum / double(n * n);
}

void Medium::findEmptyBlocks()
{
    for (int a = 0; a < 3; ++a) blockCount[a] = (std::max(dims[a] - 1, 1) + blockCells - 1) / blockCells;
    emptyBlocks.assign(std::size_t(blockCount.x) * blockCount.y * blockCount.z, 0);
    for (int bz = 0; bz < blockCount.z; ++bz)
        for (int by = 0; by < blockCount.y; ++by)
            for (int bx = 0; bx < blockCount.x; ++bx) {
                // The voxels the block's cells interpolate: [b * 4, b * 4 + 4] along each axis.
                const glm::ivec3 first(bx * blockCells, by * blockCells, bz * blockCells);
                const glm::ivec3 last = glm::min(first + blockCells, dims - 1);
                double lo = std::numeric_limits<double>::infinity(), hi = -lo;
                for (int z = first.z; z <= last.z; ++z)
                    for (int y = first.y; y <= last.y; ++y)
                        for (int x = first.x; x <= last.x; ++x) {
                            const double v = volume->value(x, y, z);
                            if (std::isnan(v)) continue;  // a value it touches is NaN: empty
                            lo = std::min(lo, v);
                            hi = std::max(hi, v);
                        }
                // Widened a little: a trilinear sum may round just past its voxels' range.
                const double margin = 1e-9 * (std::abs(lo) + std::abs(hi) + 1.0);
                const bool empty = !(lo <= hi) || !(largestOpacity(*tf, lo - margin, hi + margin) > 0.0);
                emptyBlocks[(std::size_t(bz) * blockCount.y + by) * blockCount.x + bx] = empty;
            }
}

bool Medium::inEmptyBlock(const glm::dvec3& tc) const
{
    if (emptyBlocks.empty()) return false;
    const int bx = lowerVoxel(tc.x, dims.x) / blockCells, by = lowerVoxel(tc.y, dims.y) / blockCells,
              bz = lowerVoxel(tc.z, dims.z) / blockCells;
    return emptyBlocks[(std::size_t(bz) * blockCount.y + by) * blockCount.x + bx] != 0;
}

double Medium::transmittance(const glm::dvec3& local, const glm::dvec3& l, double distance, ShadowTally& tally) const
{
    // The path: up to the light or out of the box, whichever comes first (a sample on a face,
    // or one outside it by rounding, going outwards has none).
    double length = distance;
    for (int a = 0; a < 3; ++a) {
        if (l[a] > 0.0) length = std::min(length, (0.5 * size[a] - local[a]) / l[a]);
        else if (l[a] < 0.0) length = std::min(length, (-0.5 * size[a] - local[a]) / l[a]);
    }
    if (!(length > 0.0) || !std::isfinite(length)) return 1.0;
    // Optical depth is measured in world lengths, as along the view ray.
    const double worldPerLocal = osg::Matrixd::transform3x3(osg::Vec3d(l.x, l.y, l.z), localToWorld).length();
    if (!(worldPerLocal > 0.0) || !std::isfinite(worldPerLocal)) return 1.0;
    // Steps of shadowFirstStep x Δ0 (at least two of them), halved until converged. A march
    // stops once its optical depth passes 40 (T < 4.3e-18: 0 at any tolerance).
    auto steps = std::max<std::size_t>(2, std::size_t(std::ceil(length / (shadowFirstStep * unitLength))));
    const double finestCount = std::ceil(length / (shadowFinestStep * unitLength));
    const double enough = 40.0 / worldPerLocal;
    double coarse = std::exp(-opticalDepth(*this, local, l, length, steps, enough) * worldPerLocal);
    for (;;) {
        steps *= 2;
        const double fine = std::exp(-opticalDepth(*this, local, l, length, steps, enough) * worldPerLocal);
        tally.finest = std::min(tally.finest, length / double(steps) * worldPerLocal);
        if (std::abs(fine - coarse) <= shadowTolerance) return fine;
        if (double(steps) >= finestCount) {
            tally.converged = false;
            return fine;
        }
        coarse = fine;
    }
}

double Medium::lightOnGeometry(const glm::dvec3& local, ShadowTally& tally) const
{
    if (lights.empty()) return 1.0;
    double sum = 0.0;
    for (const auto& [position, colour] : lights) {
        glm::dvec3 l = position.w == 0.0 ? glm::dvec3(position) : glm::dvec3(position) - local;
        const double distance = position.w == 0.0 ? std::numeric_limits<double>::infinity() : glm::length(l);
        if (!(glm::length(l) > 0.0)) {
            sum += 1.0;
            continue;
        }
        l = glm::normalize(l);
        // The way from `local` towards the light inside the box: [enter, leave].
        double enter = 0.0, leave = distance;
        for (int a = 0; a < 3; ++a) {
            if (l[a] == 0.0) {
                if (std::abs(local[a]) > 0.5 * size[a]) leave = -1.0;
                continue;
            }
            const double u = (-0.5 * size[a] - local[a]) / l[a], v = (0.5 * size[a] - local[a]) / l[a];
            enter = std::max(enter, std::min(u, v));
            leave = std::min(leave, std::max(u, v));
        }
        sum += leave > enter ? transmittance(local + l * enter, l, leave - enter, tally) : 1.0;
    }
    return sum / double(lights.size());
}

bool Medium::blocked(const glm::dvec3& local, const glm::dvec4& position) const
{
    if (!occluders || !occluders->occluders) return false;
    const osg::Vec3d from = osg::Vec3d(local.x, local.y, local.z) * localToWorld;
    const osg::Vec3d p(position.x, position.y, position.z);
    if (position.w != 0.0) return occluders->occluded(from, p * localToWorld);
    osg::Vec3d towards = osg::Matrixd::transform3x3(p, localToWorld);  // the local direction's image
    towards.normalize();
    const osg::BoundingSphere& bound = occluders->occluders->getBound();
    const double reach = (osg::Vec3d(bound.center()) - from).length() + bound.radius() + 1.0;
    return occluders->occluded(from, from + towards * reach);
}

}  // namespace volren::reference
