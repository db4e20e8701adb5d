#pragma once
#include "NiftiByteSource.h"

#include <cstdint>
#include <string>

namespace volren::nifti {

/// The fields volren uses from a NIfTI-1 (348-byte) or NIfTI-2 (540-byte) header, widened to
/// the NIfTI-2 types and in native byte order.
struct NiftiHeader
{
    int version = 1;                 ///< 1 or 2
    bool swapped = false;            ///< file byte order differs from this machine's
    std::size_t size = 348;          ///< header bytes: 348 or 540
    std::int64_t dim[8] = {};        ///< dim[0] = rank, dim[1..7] sizes (unused axes 1)
    int datatype = 0;                ///< NIfTI datatype code
    double pixdim[8] = {};           ///< pixdim[0] = qfac, pixdim[1..3] spacing
    double voxOffset = 0.0;          ///< byte offset of the voxels
    double slope = 0.0, intercept = 0.0;  ///< scl_slope, scl_inter (slope 0: unscaled)
    int qformCode = 0, sformCode = 0;     ///< orientation codes (0: absent)
    double quatern[3] = {};          ///< quatern_b, c, d
    double qoffset[3] = {};          ///< qoffset_x, y, z
    double srow[3][4] = {};          ///< sform rows x, y, z
    int xyztUnits = 0;               ///< xyzt_units (bits 0-2 the spatial unit: 1 m, 2 mm, 3 µm)
};

/// The spatial unit `header` states ("m", "mm", "µm"), or "" when it states none.
std::string spatialUnit(const NiftiHeader& header);

/// Reads and checks the header from `source` (magic, version, rank 1..7, positive dims).
/// Throws std::runtime_error("name: reason").
NiftiHeader readNiftiHeader(const ByteSource& source, const std::string& name);

}  // namespace volren::nifti
