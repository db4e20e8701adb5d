#include "DdsDecoder.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace volren::pvm {

namespace {

constexpr std::size_t signatureLength = 8;
constexpr std::size_t interleaveBlock = std::size_t(1) << 24;  // "v3e" blocks

/// MSB-first bits of a byte range; zero bits past its end (how the format pads its last word).
class BitReader
{
public:
    BitReader(const std::uint8_t* data, std::size_t size) : _data(data), _size(size) {}

    std::uint32_t read(int bits)
    {
        std::uint32_t value = 0;
        for (int i = 0; i < bits; ++i) {
            const std::size_t byte = _bit >> 3;
            const std::uint32_t bit = byte < _size ? (_data[byte] >> (7 - (_bit & 7))) & 1u : 0u;
            value = (value << 1) | bit;
            ++_bit;
        }
        return value;
    }
    bool pastEnd() const { return (_bit >> 3) >= _size; }
    /// Whether bits beyond the end were read as data (a valid stream never does).
    bool overrun() const { return _bit > std::uint64_t(_size) * 8; }

private:
    const std::uint8_t* _data;
    std::size_t _size;
    std::uint64_t _bit = 0;
};

/// Undoes the encoder's de-interleaving: within each chunk of `skip * block` bytes (the whole
/// stream when block is 0), the stream holds byte 0, skip, 2*skip, ... then 1, 1+skip, ...
void interleave(std::vector<std::uint8_t>& data, std::size_t skip, std::size_t block)
{
    if (skip <= 1 || data.empty()) return;
    const std::size_t chunk = block == 0 ? data.size() : skip * block;
    std::vector<std::uint8_t> scratch(std::min(chunk, data.size()));
    for (std::size_t start = 0; start < data.size(); start += chunk) {
        const std::size_t length = std::min(chunk, data.size() - start);
        const std::uint8_t* in = data.data() + start;
        for (std::size_t lane = 0; lane < skip; ++lane)
            for (std::size_t j = lane; j < length; j += skip) scratch[j] = *in++;
        std::memcpy(data.data() + start, scratch.data(), length);
    }
}

}  // namespace

bool isDds(const std::vector<std::uint8_t>& bytes)
{
    return bytes.size() >= signatureLength &&
           (std::memcmp(bytes.data(), "DDS v3d\n", signatureLength) == 0 ||
            std::memcmp(bytes.data(), "DDS v3e\n", signatureLength) == 0);
}

std::vector<std::uint8_t> decodeDds(const std::vector<std::uint8_t>& bytes, const std::string& name,
                                    std::uint64_t maxBytes)
{
    if (!isDds(bytes)) throw std::runtime_error(name + ": not a DDS stream");
    const bool blocked = bytes[6] == 'e';
    BitReader in(bytes.data() + signatureLength, bytes.size() - signatureLength);
    const std::size_t skip = in.read(2) + 1;       // bytes per voxel: the interleave width
    const std::size_t strip = in.read(16) + 1;     // row length of the predictor
    std::vector<std::uint8_t> out;
    int value = 0;
    for (;;) {
        const std::uint32_t run = in.read(7);
        if (run == 0) break;  // the end (the zero padding of the last word reads as 0)
        if (in.pastEnd()) throw std::runtime_error(name + ": truncated DDS stream");
        const std::uint32_t code = in.read(3);
        const int bits = code >= 1 ? int(code) + 1 : 0;  // 0, 2, 3, ... 8 bits per difference
        if (out.size() + run > maxBytes)
            throw std::runtime_error(name + ": DDS stream decodes to more than " + std::to_string(maxBytes) + " bytes");
        for (std::uint32_t k = 0; k < run; ++k) {
            const std::size_t i = out.size();
            const int difference = int(in.read(bits)) - ((1 << bits) >> 1);
            // Predicted from the previous byte plus the change one row (strip bytes) earlier.
            if (i > strip) value += int(out[i - strip]) - int(out[i - strip - 1]);
            value = (value + difference) & 0xff;
            out.push_back(std::uint8_t(value));
        }
        if (in.overrun()) throw std::runtime_error(name + ": truncated DDS stream");
    }
    if (out.empty()) throw std::runtime_error(name + ": empty DDS stream");
    interleave(out, skip, blocked ? interleaveBlock : 0);
    return out;
}

}  // namespace volren::pvm
