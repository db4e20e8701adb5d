#pragma once
#include "DicomSlice.h"

#include <string>
#include <vector>

namespace volren::dicom {

/// The slices of one series in volume order, and the distance between them.
struct SliceOrder
{
    std::vector<DicomSlice> slices;  ///< sorted by position along the slice normal
    double sliceSpacing = 0.0;       ///< mean distance between consecutive slices (mm); 0 when unknown
    osg::Vec3d normal{0, 0, 1};      ///< rowDirection x columnDirection
};

/// Largest relative deviation of one slice gap from the mean that still counts as uniform.
constexpr double sliceGapTolerance = 0.01;

/// Sorts `slices` by ImagePositionPatient projected on the slice normal (never by file name);
/// falls back to InstanceNumber with a warning when positions are missing. Throws
/// std::runtime_error("name: reason") for mixed slice sizes or orientations, duplicate
/// positions and non-uniform gaps (a missing slice).
SliceOrder orderSlices(std::vector<DicomSlice> slices, const std::string& name);

}  // namespace volren::dicom
