#include "NiftiOrientation.h"

#include <cmath>

namespace volren::nifti {

osg::Matrixd voxelToWorld(const NiftiHeader& h, std::string& source)
{
    if (h.sformCode > 0) {
        source = "sform";
        const auto& r = h.srow;
        // Row-vector convention: column c of the NIfTI 3x4 matrix becomes row c here.
        return osg::Matrixd(r[0][0], r[1][0], r[2][0], 0, r[0][1], r[1][1], r[2][1], 0, r[0][2], r[1][2], r[2][2], 0,
                            r[0][3], r[1][3], r[2][3], 1);
    }
    const double dx = h.pixdim[1], dy = h.pixdim[2], dz = h.pixdim[3];
    if (h.qformCode > 0) {
        source = "qform";
        double b = h.quatern[0], c = h.quatern[1], d = h.quatern[2];
        double a = 1.0 - (b * b + c * c + d * d);
        if (a < 1e-7) {  // nifti1.h: a 180-degree rotation; renormalise (b, c, d)
            const double len = std::sqrt(b * b + c * c + d * d);
            if (len > 0.0) b /= len, c /= len, d /= len;
            a = 0.0;
        } else {
            a = std::sqrt(a);
        }
        const double qfac = h.pixdim[0] < 0.0 ? -1.0 : 1.0;
        const double R[3][3] = {{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
                                {2 * (b * c + a * d), a * a + c * c - b * b - d * d, 2 * (c * d - a * b)},
                                {2 * (b * d - a * c), 2 * (c * d + a * b), a * a + d * d - c * c - b * b}};
        const double scale[3] = {dx, dy, dz * qfac};
        osg::Matrixd m;
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row) m(col, row) = R[row][col] * scale[col];
        m(3, 0) = h.qoffset[0], m(3, 1) = h.qoffset[1], m(3, 2) = h.qoffset[2];
        return m;
    }
    source = "pixdim";
    return osg::Matrixd::scale(dx, dy, dz);
}

}  // namespace volren::nifti
