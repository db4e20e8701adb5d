#pragma once
#include <volume_model/LoadProgress.h>
#include <volume_model/ZarrArrayMetadata.h>

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace volren {

/// A box of array elements: [begin, end) per dimension, slowest first.
struct ZarrBox
{
    std::vector<std::uint64_t> begin;  ///< first element per dimension
    std::vector<std::uint64_t> end;    ///< one past the last element per dimension
    std::uint64_t elementCount() const;  ///< product of end - begin (0 for an empty box)
};

/// One zarr v2 array on disk, read one chunk or one region at a time (never the whole array
/// unless asked). Values come in the host's byte order as metadata().dtype.voxelType(): u1 i1
/// u2 i2 f4 as stored, u4 i4 u8 i8 f8 converted to float32 (the nearest float). Chunk files
/// that do not exist read as the fill value (zarr's rule; the first one is logged as a
/// warning); a chunk file that is truncated, oversized or corrupt is an error naming it.
/// The const methods may run concurrently (a brick loader thread beside the renderer).
class ZarrArray
{
public:
    /// Opens the array folder `path`: reads and checks `path/.zarray`; throws
    /// std::runtime_error("path/.zarray: reason") when it is missing or bad.
    explicit ZarrArray(const std::string& path);

    const std::string& path() const { return _path; }                    ///< the array folder
    const ZarrArrayMetadata& metadata() const { return _meta; }          ///< the parsed .zarray
    VoxelType voxelType() const { return _meta.dtype.voxelType(); }      ///< type of the values read
    std::size_t voxelBytes() const { return voxelSize(voxelType()); }    ///< bytes per value read
    std::size_t dimensions() const { return _meta.shape.size(); }        ///< number of dimensions
    /// Path of chunk `index`'s file (which may not exist: a missing chunk is the fill value).
    std::string chunkPath(const std::vector<std::uint64_t>& index) const;
    /// Chunk `index` decoded into voxelType(), C order, the full chunk shape (edge chunks
    /// include zarr's padding). `missing`, when given, is set to whether the file was absent.
    /// Throws std::runtime_error naming the chunk file for a bad chunk or an index off the grid.
    std::vector<std::uint8_t> readChunk(const std::vector<std::uint64_t>& index, bool* missing = nullptr) const;
    /// Reads `box` (inside the shape) into `dst`: box.elementCount() values of voxelType(),
    /// C order, decoding each chunk it touches once. Reports the fraction of chunks done to
    /// `progress` (when given); a cancel throws std::runtime_error("path: cancelled").
    void readRegion(const ZarrBox& box, std::uint8_t* dst, const LoadProgress* progress = nullptr) const;
    /// readRegion into a new buffer.
    std::vector<std::uint8_t> readRegion(const ZarrBox& box) const;
    /// How many absent chunk files reads have met so far (each read as the fill value).
    std::uint64_t missingChunks() const { return _missing.load(); }

private:
    /// The decoded stored bytes of chunk `index`, or empty when its file is absent.
    std::vector<std::uint8_t> readStoredChunk(const std::vector<std::uint64_t>& index) const;
    /// Stored chunk bytes (chunk's own order and byte order) to voxelType() values in C order.
    std::vector<std::uint8_t> toVoxels(std::vector<std::uint8_t>&& stored) const;
    /// A whole chunk of the fill value.
    std::vector<std::uint8_t> fillChunk() const;
    void noteMissing(const std::string& file) const;

    std::string _path;
    ZarrArrayMetadata _meta;
    std::vector<std::uint8_t> _fill;  ///< the fill value as one voxelType() value
    mutable std::atomic<std::uint64_t> _missing{0};
};

}  // namespace volren
