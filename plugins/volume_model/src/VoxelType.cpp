#include <volume_model/VoxelType.h>

namespace volren {

std::size_t voxelSize(VoxelType type)
{
    switch (type) {
    case VoxelType::UInt8:
    case VoxelType::Int8: return 1;
    case VoxelType::UInt16:
    case VoxelType::Int16: return 2;
    case VoxelType::Float32: return 4;
    }
    return 0;
}

const char* voxelTypeName(VoxelType type)
{
    switch (type) {
    case VoxelType::UInt8: return "uint8";
    case VoxelType::Int8: return "int8";
    case VoxelType::UInt16: return "uint16";
    case VoxelType::Int16: return "int16";
    case VoxelType::Float32: return "float32";
    }
    return "unknown";
}

bool parseVoxelType(const std::string& name, VoxelType& type)
{
    for (VoxelType t : {VoxelType::UInt8, VoxelType::Int8, VoxelType::UInt16, VoxelType::Int16,
                        VoxelType::Float32}) {
        if (name == voxelTypeName(t)) {
            type = t;
            return true;
        }
    }
    return false;
}

double normalisedScale(VoxelType type)
{
    // GL's UNORM maps [0, 2^n-1] to [0,1]; SNORM maps [-(2^(n-1)-1), 2^(n-1)-1] to [-1,1].
    switch (type) {
    case VoxelType::UInt8: return 255.0;
    case VoxelType::Int8: return 127.0;
    case VoxelType::UInt16: return 65535.0;
    case VoxelType::Int16: return 32767.0;
    case VoxelType::Float32: return 1.0;
    }
    return 1.0;
}

}  // namespace volren
