// The reference's trilinear field: values, exact gradients, central differences, classification.
#include "Medium.h"

#include <algorithm>
#include <cmath>

namespace volren::reference {

Cell::Cell(const glm::dvec3& tc, const glm::ivec3& dims, const glm::dvec3& size)
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

glm::dvec3 Medium::centralDifferences(const glm::dvec3& tc) const
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

double Medium::value(const glm::dvec3& tc, glm::dvec3* gradient) const
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

bool Medium::classify(const glm::dvec3& tc, osg::Vec4& rgba) const
{
    const double v = value(tc);
    if (std::isnan(v)) return false;  // NaN voxels are empty
    rgba = tf->evaluate(std::clamp(v, domainMin, domainMax));
    if (!weighting.identity()) rgba.a() = float(rgba.a() * weighting(tc.x, tc.y, tc.z));
    return !(rgba.a() <= 0.0);
}

}  // namespace volren::reference
