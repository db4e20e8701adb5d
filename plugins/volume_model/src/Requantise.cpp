#include <volume_model/Requantise.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace volren {

osg::ref_ptr<Volume> requantise(const Volume& volume, VoxelType type)
{
    if (type != VoxelType::UInt8 && type != VoxelType::UInt16 && type != VoxelType::Float32)
        throw std::invalid_argument("requantise: only to UInt8, UInt16 or Float32");
    osg::ref_ptr<Volume> out = new Volume;
    out->allocate(type, volume.dims());
    out->setSpacing(volume.spacing());
    const auto [lo, hi] = volume.valueRange();
    const double top = type == VoxelType::UInt8 ? 255.0 : 65535.0;
    const double slope = type == VoxelType::Float32 ? 1.0 : (hi > lo ? (hi - lo) / top : 1.0);
    const double intercept = type == VoxelType::Float32 ? 0.0 : lo;
    for (std::size_t i = 0; i < volume.voxelCount(); ++i) {
        const double v = volume.value(i);
        if (type == VoxelType::Float32) {
            reinterpret_cast<float*>(out->data())[i] = float(v);
        } else {
            const double q = std::isfinite(v) ? std::clamp(std::round((v - intercept) / slope), 0.0, top) : 0.0;
            if (type == VoxelType::UInt8) out->data()[i] = std::uint8_t(q);
            else reinterpret_cast<std::uint16_t*>(out->data())[i] = std::uint16_t(q);
        }
    }
    out->setRescale(slope, intercept);
    out->setName(volume.getName());
    out->dirty();
    return out;
}

}  // namespace volren
