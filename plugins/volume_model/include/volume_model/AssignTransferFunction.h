#pragma once
#include <volume_model/VolumeNode.h>

#include <string>
#include <vector>

namespace volren {

/// Gives every node in `nodes` the transfer function in `file` (readTransferFunctionFile). Files
/// made for any data (ParaView presets, ImageJ lookup tables) are stretched over each node's
/// value range, as ParaView and Fiji do, unless `keepRange`; files of data values (`.tf`, 3D
/// Slicer `.vp`) are used as they are. A multi-channel node's channels all show through it
/// (their own transfer functions are dropped). Throws std::runtime_error naming the file.
void assignTransferFunctionFile(const std::vector<VolumeNode*>& nodes, const std::string& file, bool keepRange);

}  // namespace volren
