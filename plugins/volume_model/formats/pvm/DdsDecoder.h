#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace volren::pvm {

/// Whether `bytes` start with a DDS signature ("DDS v3d\n" or "DDS v3e\n"): a PVM file compressed
/// with the V^3 library's Differential Data Stream coding.
bool isDds(const std::vector<std::uint8_t>& bytes);

/// Decodes a DDS file into the bytes it compresses (for a compressed PVM: the whole uncompressed
/// PVM file, header included). The stream is an MSB-first bit stream: 2 bits interleave width,
/// 16 bits row length, then runs (7-bit count, 3-bit code width) of differences from a
/// row-predicted value, modulo 256; "v3e" de-interleaves in blocks of 2^24 bytes, "v3d" over the
/// whole stream. Output larger than `maxBytes` is refused. Throws std::runtime_error("name: ...").
std::vector<std::uint8_t> decodeDds(const std::vector<std::uint8_t>& bytes, const std::string& name,
                                    std::uint64_t maxBytes);

}  // namespace volren::pvm
