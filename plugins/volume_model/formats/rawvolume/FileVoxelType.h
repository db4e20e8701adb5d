#pragma once
#include <volume_model/VoxelType.h>

#include <cstddef>
#include <string>

namespace volren::rawvolume {

/// Voxel type as stored in a file; Int32/UInt32 become Float32 in the Volume (exact values only).
enum class FileVoxelType { UInt8, Int8, UInt16, Int16, Int32, UInt32, Float32, Float64 };

/// Bytes per stored value.
std::size_t fileVoxelSize(FileVoxelType type);
/// The Volume type `type` is kept as.
VoxelType volumeVoxelType(FileVoxelType type);
/// Lower-case name ("uint8", ..., "int32", "float32", "float64").
const char* fileVoxelTypeName(FileVoxelType type);
/// Parses volren's names (uint8, int8, uint16, int16, int32, uint32, float32, float64) and the
/// usual aliases (uchar, char, ushort, short, int, uint, float, double); false when unknown.
bool parseFileVoxelType(const std::string& name, FileVoxelType& type);

}  // namespace volren::rawvolume
