#include "FileVoxelType.h"

namespace volren::rawvolume {

std::size_t fileVoxelSize(FileVoxelType type)
{
    switch (type) {
    case FileVoxelType::UInt8: case FileVoxelType::Int8: return 1;
    case FileVoxelType::UInt16: case FileVoxelType::Int16: return 2;
    case FileVoxelType::Int32: case FileVoxelType::UInt32: case FileVoxelType::Float32: return 4;
    case FileVoxelType::Float64: return 8;
    }
    return 1;
}

VoxelType volumeVoxelType(FileVoxelType type)
{
    switch (type) {
    case FileVoxelType::UInt8: return VoxelType::UInt8;
    case FileVoxelType::Int8: return VoxelType::Int8;
    case FileVoxelType::UInt16: return VoxelType::UInt16;
    case FileVoxelType::Int16: return VoxelType::Int16;
    default: return VoxelType::Float32;
    }
}

const char* fileVoxelTypeName(FileVoxelType type)
{
    switch (type) {
    case FileVoxelType::UInt8: return "uint8";
    case FileVoxelType::Int8: return "int8";
    case FileVoxelType::UInt16: return "uint16";
    case FileVoxelType::Int16: return "int16";
    case FileVoxelType::Int32: return "int32";
    case FileVoxelType::UInt32: return "uint32";
    case FileVoxelType::Float32: return "float32";
    case FileVoxelType::Float64: return "float64";
    }
    return "?";
}

bool parseFileVoxelType(const std::string& name, FileVoxelType& type)
{
    static const struct { const char* name; FileVoxelType type; } names[] = {
        {"uint8", FileVoxelType::UInt8},   {"uchar", FileVoxelType::UInt8},   {"int8", FileVoxelType::Int8},
        {"char", FileVoxelType::Int8},     {"uint16", FileVoxelType::UInt16}, {"ushort", FileVoxelType::UInt16},
        {"int16", FileVoxelType::Int16},   {"short", FileVoxelType::Int16},   {"int32", FileVoxelType::Int32},
        {"int", FileVoxelType::Int32},     {"uint32", FileVoxelType::UInt32}, {"uint", FileVoxelType::UInt32},
        {"float32", FileVoxelType::Float32}, {"float", FileVoxelType::Float32}, {"float64", FileVoxelType::Float64},
        {"double", FileVoxelType::Float64},
    };
    for (const auto& n : names)
        if (name == n.name) {
            type = n.type;
            return true;
        }
    return false;
}

}  // namespace volren::rawvolume
