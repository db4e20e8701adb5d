#pragma once
#include <volume_model/ZarrArrayMetadata.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace volren {

/// Decodes the stored bytes of one chunk file `name` with `compressor` (null, blosc, zlib or
/// gzip) into exactly `expected` bytes. Checks before allocating: a raw chunk must hold exactly
/// `expected` bytes, a blosc header must promise exactly that many, a zlib stream must be long
/// enough to expand to them. Throws std::runtime_error("name: reason") for a truncated,
/// oversized or corrupt chunk and for one that decodes to a different size.
std::vector<std::uint8_t> decodeZarrChunk(const std::uint8_t* stored, std::size_t size, const ZarrCompressor& compressor,
                                          std::size_t expected, const std::string& name);

/// Compresses `size` bytes of elements of `typesize` bytes as `compressor` says (blosc's
/// shuffle -1 means bit shuffle for 1-byte elements, byte shuffle otherwise, as numcodecs does).
/// Throws std::runtime_error when the compressor fails.
std::vector<std::uint8_t> encodeZarrChunk(const std::uint8_t* data, std::size_t size, std::size_t typesize,
                                          const ZarrCompressor& compressor);

}  // namespace volren
