#pragma once
#include <osgDB/Options>

#include <cstdint>
#include <string>
#include <vector>

namespace volren::rawvolume {

/// How the voxel bytes of one data file are stored.
enum class Compression { None, Zlib };  ///< Zlib: a gzip or zlib stream (detected from its header)

/// One file (or the tail of a header file) that holds an equal share of a volume's voxel bytes.
struct PayloadPart
{
    std::string path;                     ///< data file (absolute or relative to the working folder)
    std::uint64_t offset = 0;             ///< byte where reading starts (e.g. the end of an attached header)
    std::uint64_t lineSkip = 0;           ///< text lines skipped after `offset` (NRRD "line skip")
    std::int64_t byteSkip = 0;            ///< bytes skipped after the lines; -1: the data are the file's last bytes (no compression)
    Compression compression = Compression::None;  ///< stored form of the bytes
    std::uint64_t compressedSize = 0;     ///< bytes of compressed input to use; 0 = up to the end of the file
};

/// Reads `bytes` voxel bytes, split evenly over `parts`, straight into `dst`. Uncompressed data
/// must fill the rest of its file exactly (a longer or shorter file is a size mismatch), a
/// compressed stream must decode to exactly its share. Reports progress per chunk to the
/// callback in `options`. Throws std::runtime_error("name: reason") on any failure or on
/// cancellation ("name: cancelled").
void readPayload(const std::vector<PayloadPart>& parts, std::uint8_t* dst, std::uint64_t bytes,
                 const std::string& name, const osgDB::Options* options);

/// The file byte where the voxels of an uncompressed `part` start (after its offset, skipped
/// lines and bytes), checking as readPayload does that exactly `bytes` voxel bytes follow.
/// Throws std::runtime_error("name: reason") as readPayload does.
std::uint64_t uncompressedPayloadStart(const PayloadPart& part, std::uint64_t bytes, const std::string& name);

/// Cheap check, before the voxel buffer is allocated, that `parts` can hold `bytes` voxel
/// bytes: each data file must exist and hold its share from its offset (a compressed one at
/// most deflate's 1032:1 expansion of it). Throws std::runtime_error("name: truncated: ...")
/// otherwise, so that a small header claiming gigabytes fails without allocating them.
void checkPayloadFits(const std::vector<PayloadPart>& parts, std::uint64_t bytes, const std::string& name);

/// Reverses the byte order of `count` values of `width` bytes in place.
void swapBytes(std::uint8_t* data, std::size_t count, std::size_t width);

}  // namespace volren::rawvolume
