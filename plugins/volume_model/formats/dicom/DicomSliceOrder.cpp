#include "DicomSliceOrder.h"

#include <osg/Notify>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace volren::dicom {

namespace {

std::string fileName(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string describe(const osg::Vec3d& v)
{
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

}  // namespace

SliceOrder orderSlices(std::vector<DicomSlice> slices, const std::string& name)
{
    if (slices.empty()) throw std::runtime_error(name + ": no DICOM slices");
    const DicomSlice& first = slices.front();
    for (const DicomSlice& s : slices) {
        if (s.rows <= 0 || s.columns <= 0)
            throw std::runtime_error(s.file + ": image size " + std::to_string(s.columns) + "x" + std::to_string(s.rows) +
                                     " (Columns x Rows) is not positive");
        if (s.rows != first.rows || s.columns != first.columns)
            throw std::runtime_error(name + ": mixed slice sizes in the series: " + fileName(first.file) + " is " +
                                     std::to_string(first.columns) + "x" + std::to_string(first.rows) + ", " +
                                     fileName(s.file) + " is " + std::to_string(s.columns) + "x" +
                                     std::to_string(s.rows));
        if (s.hasOrientation && first.hasOrientation &&
            ((s.rowDirection - first.rowDirection).length() > 1e-3 ||
             (s.columnDirection - first.columnDirection).length() > 1e-3))
            throw std::runtime_error(name + ": mixed slice orientations in the series: " + fileName(first.file) +
                                     " and " + fileName(s.file));
    }

    SliceOrder order;
    if (first.hasOrientation) order.normal = first.rowDirection ^ first.columnDirection;
    const bool positioned = std::all_of(slices.begin(), slices.end(), [](const DicomSlice& s) { return s.hasPosition; });
    if (slices.size() == 1) {
        order.slices = std::move(slices);
        return order;
    }
    if (!positioned) {
        OSG_WARN << name << ": slices lack ImagePositionPatient; ordered by InstanceNumber, slice spacing unknown"
                 << std::endl;
        std::stable_sort(slices.begin(), slices.end(),
                         [](const DicomSlice& a, const DicomSlice& b) { return a.instance < b.instance; });
        order.slices = std::move(slices);
        return order;
    }

    const osg::Vec3d n = order.normal;
    std::stable_sort(slices.begin(), slices.end(),
                     [&n](const DicomSlice& a, const DicomSlice& b) { return a.position * n < b.position * n; });
    std::vector<double> gaps;
    for (std::size_t i = 1; i < slices.size(); ++i) {
        const double gap = slices[i].position * n - slices[i - 1].position * n;
        if (!(gap > 1e-4))
            throw std::runtime_error(name + ": two slices at the same position " + describe(slices[i].position) +
                                     ": " + fileName(slices[i - 1].file) + " and " + fileName(slices[i].file) +
                                     " (several acquisitions in one series are not supported)");
        gaps.push_back(gap);
    }
    const double total = slices.back().position * n - slices.front().position * n;
    const double mean = total / double(gaps.size());
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        if (std::fabs(gaps[i] - mean) > sliceGapTolerance * mean) {
            std::ostringstream s;
            s << name << ": slice spacing is not uniform: " << gaps[i] << " mm between " << fileName(slices[i].file)
              << " and " << fileName(slices[i + 1].file) << ", mean " << mean << " mm (missing or extra slice?)";
            throw std::runtime_error(s.str());
        }
    }
    order.sliceSpacing = mean;
    order.slices = std::move(slices);
    return order;
}

}  // namespace volren::dicom
