#pragma once
#include <volume_model/VoxelType.h>

#include <cstdint>
#include <string>
#include <vector>

namespace volren {

/// Element type of a zarr v2 array, as its `dtype` string says ("<u2", ">f4", "|u1", ...).
struct ZarrDataType
{
    char byteOrder = '|';  ///< '<' little endian, '>' big endian, '|' not applicable (one byte)
    char kind = 'u';       ///< 'u' unsigned integer, 'i' signed integer, 'f' floating point
    int size = 1;          ///< bytes per element: 1, 2, 4 or 8

    /// The dtype string ("<u2").
    std::string str() const;
    /// Voxel type values are read into: u1 i1 u2 i2 f4 as stored; u4 i4 u8 i8 f8 are converted
    /// to float32 (rounded to the nearest float: integers above 2^24 and doubles lose digits).
    VoxelType voxelType() const;
    /// Whether reading converts the values (voxelType() differs from the stored type).
    bool converted() const;
    /// Whether values must be byte-swapped to the host's order.
    bool needsSwap() const;
};

/// The `compressor` of a zarr v2 array.
struct ZarrCompressor
{
    std::string id;             ///< "" (null: chunks stored raw), "blosc", "zlib" or "gzip"
    std::string cname = "lz4";  ///< blosc: inner codec (any that this blosc build offers)
    int level = 5;              ///< blosc clevel or zlib/gzip level, 0-9
    int shuffle = 1;            ///< blosc: 0 none, 1 byte shuffle, 2 bit shuffle
    int blocksize = 0;          ///< blosc: block size in bytes, 0 automatic
};

/// A parsed and checked `.zarray` (zarr v2 array metadata): dimensions at least 1, every size
/// positive, element count and chunk bytes free of overflow, chunks at most maxChunkBytes.
struct ZarrArrayMetadata
{
    /// Largest decoded chunk accepted (512 MiB); a larger one is refused, never allocated.
    static constexpr std::uint64_t maxChunkBytes = std::uint64_t(1) << 29;

    std::vector<std::uint64_t> shape;   ///< array size per dimension, slowest first
    std::vector<std::uint64_t> chunks;  ///< chunk size per dimension
    ZarrDataType dtype;                 ///< stored element type
    ZarrCompressor compressor;          ///< how chunk files are compressed
    bool fortranOrder = false;          ///< order "F": a chunk's elements run first dimension fastest
    double fillValue = 0.0;             ///< value of elements in missing chunks (NaN allowed for floats; null reads as 0)
    char separator = '.';               ///< dimension_separator of chunk keys: '.' ("0.1.2") or '/' ("0/1/2")

    std::uint64_t elementCount() const;       ///< product of shape
    std::uint64_t chunkElementCount() const;  ///< product of chunks
    std::uint64_t chunkBytes() const;         ///< bytes of one decoded chunk as stored (elements * dtype.size)
    std::vector<std::uint64_t> chunkGrid() const;  ///< chunks per dimension (shape / chunks, rounded up)
    /// Chunk key of chunk `index` ("0.1.2" or "0/1/2"), a path relative to the array folder.
    std::string chunkKey(const std::vector<std::uint64_t>& index) const;
    /// The `.zarray` JSON text (zarr_format 2) that parses back to this metadata.
    std::string toJson() const;
};

/// Parses `.zarray` text. Throws std::runtime_error("name: reason") for malformed JSON, a
/// zarr_format other than 2, unknown dtypes, compressors or filters, a bad order, fill value or
/// separator, and shapes or chunks that are empty, non-positive, mismatched or overflowing.
ZarrArrayMetadata parseZarrArrayMetadata(const std::string& text, const std::string& name);

}  // namespace volren
