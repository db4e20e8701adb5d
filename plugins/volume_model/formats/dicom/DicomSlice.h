#pragma once
#include <osg/Vec3d>

#include <string>

namespace volren::dicom {

/// What the header of one DICOM slice file says about its place in a series.
struct DicomSlice
{
    std::string file;            ///< path of the slice file
    std::string seriesUid;       ///< SeriesInstanceUID (0020,000E)
    int rows = 0, columns = 0;   ///< (0028,0010), (0028,0011)
    int frames = 1;              ///< NumberOfFrames (0028,0008); 1 when absent
    bool hasPosition = false;    ///< ImagePositionPatient (0020,0032) present and valid
    osg::Vec3d position;         ///< patient position of the first voxel (mm)
    bool hasOrientation = false; ///< ImageOrientationPatient (0020,0037) present and valid
    osg::Vec3d rowDirection{1, 0, 0}, columnDirection{0, 1, 0};  ///< unit directions of i and j
    int instance = 0;            ///< InstanceNumber (0020,0013); 0 when absent
};

}  // namespace volren::dicom
