#include <volume_model/ZarrArray.h>
#include <volume_model/ZarrCodec.h>

#include <osg/Notify>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace volren {

namespace fs = std::filesystem;

namespace {

std::string readTextFile(const std::string& file)
{
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (status.type() == fs::file_type::not_found) throw std::runtime_error(file + ": no such file");
    if (status.type() == fs::file_type::directory) throw std::runtime_error(file + ": is a directory");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file + ": cannot open: " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw std::runtime_error(file + ": read failed");
    return text.str();
}

std::string indexText(const std::vector<std::uint64_t>& values)
{
    std::string text = "[";
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + std::to_string(values[i]);
    return text + "]";
}

void swapBytes(std::uint8_t* data, std::size_t count, std::size_t width)
{
    for (std::size_t i = 0; i < count; ++i) std::reverse(data + i * width, data + (i + 1) * width);
}

/// One stored value (host byte order) of `type` at `p` as a double.
double storedValue(const std::uint8_t* p, const ZarrDataType& type)
{
    const auto load = [p](auto value) {
        std::memcpy(&value, p, sizeof(value));
        return double(value);
    };
    if (type.kind == 'f') return type.size == 4 ? load(float()) : load(double());
    switch (type.size) {
    case 1: return type.kind == 'u' ? load(std::uint8_t()) : load(std::int8_t());
    case 2: return type.kind == 'u' ? load(std::uint16_t()) : load(std::int16_t());
    case 4: return type.kind == 'u' ? load(std::uint32_t()) : load(std::int32_t());
    default: return type.kind == 'u' ? load(std::uint64_t()) : load(std::int64_t());
    }
}

/// `value` stored as one value of `type` into `p`.
void storeVoxel(double value, VoxelType type, std::uint8_t* p)
{
    const auto store = [p](auto v) { std::memcpy(p, &v, sizeof(v)); };
    switch (type) {
    case VoxelType::UInt8: store(std::uint8_t(value)); break;
    case VoxelType::Int8: store(std::int8_t(value)); break;
    case VoxelType::UInt16: store(std::uint16_t(value)); break;
    case VoxelType::Int16: store(std::int16_t(value)); break;
    case VoxelType::Float32: store(float(value)); break;
    }
}

}  // namespace

std::uint64_t ZarrBox::elementCount() const
{
    std::uint64_t n = 1;
    for (std::size_t d = 0; d < begin.size() && d < end.size(); ++d) n *= end[d] > begin[d] ? end[d] - begin[d] : 0;
    return n;
}

ZarrArray::ZarrArray(const std::string& path) : _path(path)
{
    while (_path.size() > 1 && _path.back() == '/') _path.pop_back();
    const std::string file = _path + "/.zarray";
    _meta = parseZarrArrayMetadata(readTextFile(file), file);
    _fill.resize(voxelBytes());
    storeVoxel(_meta.fillValue, voxelType(), _fill.data());
}

std::string ZarrArray::chunkPath(const std::vector<std::uint64_t>& index) const
{
    return _path + "/" + _meta.chunkKey(index);
}

std::vector<std::uint8_t> ZarrArray::readStoredChunk(const std::vector<std::uint64_t>& index) const
{
    const std::string file = chunkPath(index);
    const std::vector<std::uint64_t> grid = _meta.chunkGrid();
    bool inside = index.size() == grid.size();
    for (std::size_t d = 0; inside && d < grid.size(); ++d) inside = index[d] < grid[d];
    if (!inside) throw std::runtime_error(file + ": chunk index " + indexText(index) + " is outside the chunk grid " + indexText(grid));

    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (status.type() == fs::file_type::not_found) return {};
    if (status.type() == fs::file_type::directory)
        throw std::runtime_error(file + ": is a directory, not a chunk (dimension_separator \"" + std::string(1, _meta.separator) +
                                 "\" in .zarray?)");
    const std::uint64_t expected = _meta.chunkBytes();
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec) throw std::runtime_error(file + ": cannot read chunk: " + ec.message());
    // Compressed data may be a little larger than its content; far larger is not a chunk.
    if (size > expected + expected / 8 + 4096)
        throw std::runtime_error(file + ": oversized chunk (" + std::to_string(size) + " bytes for a chunk of " +
                                 std::to_string(expected) + " bytes)");
    std::vector<std::uint8_t> stored(size);
    std::ifstream in(file, std::ios::binary);
    if (!in || !in.read(reinterpret_cast<char*>(stored.data()), std::streamsize(size)))
        throw std::runtime_error(file + ": cannot read chunk: " + std::strerror(errno));
    std::vector<std::uint8_t> decoded = decodeZarrChunk(stored.data(), stored.size(), _meta.compressor, expected, file);
    if (decoded.empty()) throw std::runtime_error(file + ": empty chunk");
    return decoded;
}

std::vector<std::uint8_t> ZarrArray::toVoxels(std::vector<std::uint8_t>&& stored) const
{
    const ZarrDataType& t = _meta.dtype;
    const std::size_t width = std::size_t(t.size);
    const std::size_t count = stored.size() / width;
    const std::size_t n = _meta.chunks.size();
    if (_meta.fortranOrder && n > 1) {
        // Element (i0, ..., in-1) of a chunk sits at i0 + c0 * (i1 + c1 * (...)) in F order.
        std::vector<std::uint64_t> fStride(n, 1);
        for (std::size_t d = 1; d < n; ++d) fStride[d] = fStride[d - 1] * _meta.chunks[d - 1];
        std::vector<std::uint8_t> c(stored.size());
        std::vector<std::uint64_t> idx(n, 0);
        const std::uint64_t rowLength = _meta.chunks[n - 1];
        for (std::size_t out = 0; out < count; out += rowLength) {
            std::uint64_t offset = 0;
            for (std::size_t d = 0; d + 1 < n; ++d) offset += idx[d] * fStride[d];
            for (std::uint64_t i = 0; i < rowLength; ++i)
                std::memcpy(c.data() + (out + i) * width, stored.data() + (offset + i * fStride[n - 1]) * width, width);
            for (std::size_t d = n - 1; d-- > 0;) {
                if (++idx[d] < _meta.chunks[d]) break;
                idx[d] = 0;
            }
        }
        stored.swap(c);
    }
    if (t.needsSwap()) swapBytes(stored.data(), count, width);
    if (!t.converted()) return stored;
    std::vector<std::uint8_t> voxels(count * sizeof(float));
    for (std::size_t i = 0; i < count; ++i) storeVoxel(storedValue(stored.data() + i * width, t), VoxelType::Float32, voxels.data() + i * 4);
    return voxels;
}

std::vector<std::uint8_t> ZarrArray::fillChunk() const
{
    const std::size_t vb = voxelBytes();
    std::vector<std::uint8_t> chunk(std::size_t(_meta.chunkElementCount()) * vb);
    for (std::size_t i = 0; i < chunk.size(); i += vb) std::memcpy(chunk.data() + i, _fill.data(), vb);
    return chunk;
}

void ZarrArray::noteMissing(const std::string& file) const
{
    if (_missing.fetch_add(1) == 0) {
        OSG_WARN << file << ": chunk file missing; its voxels read as the fill value " << _meta.fillValue << std::endl;
    } else {
        OSG_INFO << file << ": chunk file missing; its voxels read as the fill value" << std::endl;
    }
}

std::vector<std::uint8_t> ZarrArray::readChunk(const std::vector<std::uint64_t>& index, bool* missing) const
{
    std::vector<std::uint8_t> stored = readStoredChunk(index);
    if (missing) *missing = stored.empty();
    if (stored.empty()) {
        noteMissing(chunkPath(index));
        return fillChunk();
    }
    return toVoxels(std::move(stored));
}

void ZarrArray::readRegion(const ZarrBox& box, std::uint8_t* dst, const LoadProgress* progress) const
{
    const std::size_t n = dimensions();
    if (box.begin.size() != n || box.end.size() != n)
        throw std::runtime_error(_path + ": region of " + std::to_string(box.begin.size()) + " dimensions for an array of " + std::to_string(n));
    for (std::size_t d = 0; d < n; ++d)
        if (box.begin[d] > box.end[d] || box.end[d] > _meta.shape[d])
            throw std::runtime_error(_path + ": region " + indexText(box.begin) + " - " + indexText(box.end) + " is not inside the shape " +
                                     indexText(_meta.shape));
    if (box.elementCount() == 0) return;

    const std::size_t vb = voxelBytes();
    std::vector<std::uint64_t> boxStride(n, 1), chunkStride(n, 1), first(n), last(n);
    for (std::size_t d = n - 1; d-- > 0;) {
        boxStride[d] = boxStride[d + 1] * (box.end[d + 1] - box.begin[d + 1]);
        chunkStride[d] = chunkStride[d + 1] * _meta.chunks[d + 1];
    }
    std::uint64_t total = 1;
    for (std::size_t d = 0; d < n; ++d) {
        first[d] = box.begin[d] / _meta.chunks[d];
        last[d] = (box.end[d] - 1) / _meta.chunks[d];
        total *= last[d] - first[d] + 1;
    }

    std::vector<std::uint64_t> chunk = first, lo(n), hi(n), at(n);
    for (std::uint64_t done = 0; done < total;) {
        for (std::size_t d = 0; d < n; ++d) {
            const std::uint64_t origin = chunk[d] * _meta.chunks[d];
            lo[d] = std::max(box.begin[d], origin);
            hi[d] = std::min(box.end[d], origin + _meta.chunks[d]);
        }
        std::vector<std::uint8_t> stored = readStoredChunk(chunk);
        const bool absent = stored.empty();
        std::vector<std::uint8_t> voxels;
        if (absent) noteMissing(chunkPath(chunk));
        else voxels = toVoxels(std::move(stored));
        // Copy the intersection row by row (rows along the last, contiguous dimension).
        const std::uint64_t row = hi[n - 1] - lo[n - 1];
        at = lo;
        for (;;) {
            std::uint64_t to = 0, from = 0;
            for (std::size_t d = 0; d < n; ++d) {
                to += (at[d] - box.begin[d]) * boxStride[d];
                from += (at[d] - chunk[d] * _meta.chunks[d]) * chunkStride[d];
            }
            std::uint8_t* out = dst + to * vb;
            if (absent)
                for (std::uint64_t i = 0; i < row; ++i) std::memcpy(out + i * vb, _fill.data(), vb);
            else
                std::memcpy(out, voxels.data() + from * vb, row * vb);
            std::size_t d = n - 1;
            while (d-- > 0) {
                if (++at[d] < hi[d]) break;
                at[d] = lo[d];
            }
            if (d == std::size_t(-1)) break;
        }
        ++done;
        if (progress && *progress && !(*progress)(double(done) / double(total))) throw std::runtime_error(_path + ": cancelled");
        for (std::size_t d = n; d-- > 0;) {
            if (++chunk[d] <= last[d]) break;
            chunk[d] = first[d];
        }
    }
}

std::vector<std::uint8_t> ZarrArray::readRegion(const ZarrBox& box) const
{
    std::vector<std::uint8_t> out(std::size_t(box.elementCount()) * voxelBytes());
    readRegion(box, out.data());
    return out;
}

}  // namespace volren
