#pragma once
#include <cstddef>
#include <string>

namespace volren {

/// Storage type of one voxel; kept at full precision from file to GPU.
enum class VoxelType { UInt8, Int8, UInt16, Int16, Float32 };

/// Bytes per voxel of `type`.
std::size_t voxelSize(VoxelType type);
/// Lower-case name ("uint8", "int16", "float32", ...).
const char* voxelTypeName(VoxelType type);
/// Parses a name produced by voxelTypeName; returns false when unknown.
bool parseVoxelType(const std::string& name, VoxelType& type);
/// Scale that maps a normalised GPU texel of `type` back to the stored integer (1 for float).
double normalisedScale(VoxelType type);

}  // namespace volren
