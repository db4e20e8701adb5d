#pragma once
#include <volume_model/Volume.h>

#include <cstdint>
#include <string>
#include <vector>

namespace volren::pvm {

/// Parses a whole PVM file ("PVM", "PVM2" or "PVM3" header; 1 byte or 2 bytes big-endian per
/// voxel) held in `bytes`, uncompressed or DDS-compressed ("DDS v3d"/"DDS v3e", decodeDds).
/// `name` is used in messages. Throws std::runtime_error("name: reason").
osg::ref_ptr<Volume> readPvm(const std::vector<std::uint8_t>& bytes, const std::string& name);

}  // namespace volren::pvm
