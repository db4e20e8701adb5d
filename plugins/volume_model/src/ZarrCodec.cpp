#include <volume_model/ZarrCodec.h>

#include <blosc.h>
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace volren {

namespace {

std::string bytesText(std::uint64_t n)
{
    return std::to_string(n) + (n == 1 ? " byte" : " bytes");
}

std::vector<std::uint8_t> decodeBlosc(const std::uint8_t* stored, std::size_t size, std::size_t expected, const std::string& name)
{
    if (size < BLOSC_MIN_HEADER_LENGTH)
        throw std::runtime_error(name + ": truncated blosc chunk (" + bytesText(size) + ", shorter than its 16-byte header)");
    std::size_t nbytes = 0, cbytes = 0, blocksize = 0;
    blosc_cbuffer_sizes(stored, &nbytes, &cbytes, &blocksize);
    if (cbytes > size)
        throw std::runtime_error(name + ": truncated blosc chunk (its header says " + bytesText(cbytes) + ", the file holds " +
                                 bytesText(size) + ")");
    if (cbytes < size)
        throw std::runtime_error(name + ": blosc chunk of " + bytesText(cbytes) + " followed by " + bytesText(size - cbytes) +
                                 " of other data");
    if (nbytes != expected)
        throw std::runtime_error(name + ": blosc chunk decodes to " + bytesText(nbytes) + ", but the chunk shape and dtype of .zarray need " +
                                 bytesText(expected));
    std::size_t validated = 0;
    if (blosc_cbuffer_validate(stored, size, &validated) != 0 || validated != expected)
        throw std::runtime_error(name + ": corrupt blosc chunk (its header does not check out)");
    std::vector<std::uint8_t> out(expected);
    if (expected == 0) return out;
    const int got = blosc_decompress_ctx(stored, out.data(), out.size(), 1);
    if (got < 0 || std::size_t(got) != expected) throw std::runtime_error(name + ": corrupt blosc chunk (decompression failed)");
    return out;
}

std::vector<std::uint8_t> decodeZlib(const std::uint8_t* stored, std::size_t size, std::size_t expected, const std::string& name,
                                     const std::string& codec)
{
    // deflate expands at most 1032:1; a shorter stream cannot hold the chunk.
    if (expected / 1032 > size + 64)
        throw std::runtime_error(name + ": truncated " + codec + " chunk (" + bytesText(size) + " cannot decode to " + bytesText(expected) + ")");
    std::vector<std::uint8_t> out(expected);
    z_stream zs{};
    if (inflateInit2(&zs, 15 + 32) != Z_OK) throw std::runtime_error(name + ": cannot start zlib decompression");
    std::size_t in = 0, produced = 0;
    std::uint8_t extra[64];  // where output past `expected` goes: any is an error
    bool overflow = false;
    int ret = Z_OK;
    for (;;) {
        const std::size_t inChunk = std::min<std::size_t>(size - in, UINT_MAX);
        zs.next_in = const_cast<std::uint8_t*>(stored + in);
        zs.avail_in = unsigned(inChunk);
        const bool full = produced == expected;
        zs.next_out = full ? extra : out.data() + produced;
        zs.avail_out = full ? unsigned(sizeof(extra)) : unsigned(std::min<std::size_t>(expected - produced, UINT_MAX));
        const unsigned before = zs.avail_out;
        ret = inflate(&zs, Z_NO_FLUSH);
        in += inChunk - zs.avail_in;
        if (full) overflow = zs.avail_out != before;
        else produced += before - zs.avail_out;
        if (overflow || ret != Z_OK) break;
        if (in == size && zs.avail_out != 0) {  // all input used, room left, no stream end
            ret = Z_BUF_ERROR;
            break;
        }
    }
    const std::string message = zs.msg ? zs.msg : "";
    inflateEnd(&zs);
    if (overflow)
        throw std::runtime_error(name + ": " + codec + " chunk decodes to more than " + bytesText(expected) +
                                 " (the chunk shape and dtype of .zarray need exactly that)");
    if (ret == Z_STREAM_END) {
        if (produced != expected)
            throw std::runtime_error(name + ": " + codec + " chunk decodes to " + bytesText(produced) + ", but the chunk shape and dtype of .zarray need " +
                                     bytesText(expected));
        if (in != size)
            throw std::runtime_error(name + ": " + codec + " chunk followed by " + bytesText(size - in) + " of other data");
        return out;
    }
    if (ret == Z_BUF_ERROR)
        throw std::runtime_error(name + ": truncated " + codec + " chunk (the stream ends after " + bytesText(produced) + " of " +
                                 bytesText(expected) + ")");
    throw std::runtime_error(name + ": corrupt " + codec + " chunk" + (message.empty() ? std::string() : " (" + message + ")"));
}

}  // namespace

std::vector<std::uint8_t> decodeZarrChunk(const std::uint8_t* stored, std::size_t size, const ZarrCompressor& compressor,
                                          std::size_t expected, const std::string& name)
{
    if (compressor.id.empty()) {
        if (size < expected)
            throw std::runtime_error(name + ": truncated chunk (" + bytesText(size) + ", the chunk shape and dtype of .zarray need " +
                                     bytesText(expected) + ")");
        if (size > expected)
            throw std::runtime_error(name + ": oversized chunk (" + bytesText(size) + ", the chunk shape and dtype of .zarray need " +
                                     bytesText(expected) + ")");
        return std::vector<std::uint8_t>(stored, stored + size);
    }
    if (compressor.id == "blosc") return decodeBlosc(stored, size, expected, name);
    if (compressor.id == "zlib" || compressor.id == "gzip") return decodeZlib(stored, size, expected, name, compressor.id);
    throw std::runtime_error(name + ": unknown compressor \"" + compressor.id + "\"");
}

std::vector<std::uint8_t> encodeZarrChunk(const std::uint8_t* data, std::size_t size, std::size_t typesize,
                                          const ZarrCompressor& compressor)
{
    if (compressor.id.empty()) return std::vector<std::uint8_t>(data, data + size);
    if (compressor.id == "blosc") {
        if (size > std::size_t(BLOSC_MAX_BUFFERSIZE)) throw std::runtime_error("chunk too large for blosc");
        const int shuffle = compressor.shuffle >= 0 ? compressor.shuffle : (typesize == 1 ? BLOSC_BITSHUFFLE : BLOSC_SHUFFLE);
        std::vector<std::uint8_t> out(size + BLOSC_MAX_OVERHEAD);
        const int n = blosc_compress_ctx(compressor.level, shuffle, typesize, size, data, out.data(), out.size(),
                                         compressor.cname.c_str(), std::size_t(compressor.blocksize), 1);
        if (n <= 0) throw std::runtime_error("blosc " + compressor.cname + " compression failed");
        out.resize(std::size_t(n));
        return out;
    }
    if (compressor.id == "zlib" || compressor.id == "gzip") {
        z_stream zs{};
        const int windowBits = compressor.id == "gzip" ? 15 + 16 : 15;
        if (deflateInit2(&zs, compressor.level, Z_DEFLATED, windowBits, 8, Z_DEFAULT_STRATEGY) != Z_OK)
            throw std::runtime_error("cannot start " + compressor.id + " compression");
        std::vector<std::uint8_t> out(deflateBound(&zs, uLong(size)) + 32);
        zs.next_in = const_cast<std::uint8_t*>(data);
        zs.avail_in = unsigned(size);
        zs.next_out = out.data();
        zs.avail_out = unsigned(out.size());
        const int ret = deflate(&zs, Z_FINISH);
        out.resize(zs.total_out);
        deflateEnd(&zs);
        if (ret != Z_STREAM_END) throw std::runtime_error(compressor.id + " compression did not finish");
        return out;
    }
    throw std::runtime_error("unknown compressor \"" + compressor.id + "\"");
}

}  // namespace volren
