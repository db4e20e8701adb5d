#include "ZarrJson.h"

#include <volume_model/ZarrArrayMetadata.h>

#include <blosc.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace volren {

namespace {

using zarrjson::Json;
using zarrjson::shortText;

std::string listText(const std::vector<std::uint64_t>& values)
{
    std::string text = "[";
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + std::to_string(values[i]);
    return text + "]";
}

ZarrDataType parseDataType(const Json& value, const std::string& name)
{
    if (value.is_array()) throw std::runtime_error(name + ": structured dtype " + shortText(value) + " is not supported");
    if (!value.is_string()) throw std::runtime_error(name + ": dtype is " + shortText(value) + ", not a string");
    const std::string text = value.get<std::string>();
    const auto unknown = [&](const std::string& why) {
        return std::runtime_error(name + ": unknown dtype \"" + text + "\" (" + why +
                                  "; volren reads u1 i1 u2 i2 f4, and u4 i4 u8 i8 f8 as float32)");
    };
    if (text.size() != 3) throw unknown("not a byte order, kind and size");
    ZarrDataType t;
    t.byteOrder = text[0];
    t.kind = text[1];
    if (t.byteOrder != '<' && t.byteOrder != '>' && t.byteOrder != '|') throw unknown("byte order must be <, > or |");
    if (t.kind != 'u' && t.kind != 'i' && t.kind != 'f') throw unknown("kind must be u, i or f");
    if (text[2] < '1' || text[2] > '9') throw unknown("bad size");
    t.size = text[2] - '0';
    const bool integerSize = t.size == 1 || t.size == 2 || t.size == 4 || t.size == 8;
    if (t.kind == 'f' ? (t.size != 4 && t.size != 8) : !integerSize) throw unknown("unsupported size");
    if (t.byteOrder == '|' && t.size > 1) throw unknown("byte order | on a multi-byte type");
    return t;
}

ZarrCompressor parseCompressor(const Json& value, const std::string& name)
{
    ZarrCompressor c;
    if (value.is_null()) return c;
    if (!value.is_object() || !value.contains("id") || !value["id"].is_string())
        throw std::runtime_error(name + ": compressor is " + shortText(value) + ", not null or an object with an \"id\"");
    c.id = value["id"].get<std::string>();
    const auto integer = [&](const char* key, int lo, int hi, int fallback) {
        if (!value.contains(key) || value[key].is_null()) return fallback;
        const Json& v = value[key];
        if (!v.is_number_integer() || v.get<std::int64_t>() < lo || v.get<std::int64_t>() > hi)
            throw std::runtime_error(name + ": compressor " + c.id + " " + key + " is " + shortText(v) + ", not a whole number in [" +
                                     std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return int(v.get<std::int64_t>());
    };
    if (c.id == "blosc") {
        if (!value.contains("cname") || !value["cname"].is_string())
            throw std::runtime_error(name + ": compressor blosc has no \"cname\" string");
        c.cname = value["cname"].get<std::string>();
        std::string available = blosc_list_compressors();
        bool found = false;
        std::istringstream names(available);
        for (std::string n; std::getline(names, n, ',');) found = found || n == c.cname;
        if (!found)
            throw std::runtime_error(name + ": unknown blosc codec \"" + c.cname + "\" (this blosc offers " + available + ")");
        c.level = integer("clevel", 0, 9, 5);
        c.shuffle = integer("shuffle", -1, 2, 1);
        c.blocksize = integer("blocksize", 0, std::numeric_limits<int>::max(), 0);
    } else if (c.id == "zlib" || c.id == "gzip") {
        c.level = integer("level", -1, 9, 1);
    } else {
        throw std::runtime_error(name + ": unknown compressor \"" + c.id + "\" (volren reads null, blosc, zlib and gzip)");
    }
    return c;
}

double parseFillValue(const Json& value, const ZarrDataType& t, const std::string& name)
{
    if (value.is_null()) return 0.0;
    if (value.is_string()) {
        const std::string s = value.get<std::string>();
        double v = 0.0;
        if (s == "NaN") v = std::numeric_limits<double>::quiet_NaN();
        else if (s == "Infinity") v = std::numeric_limits<double>::infinity();
        else if (s == "-Infinity") v = -std::numeric_limits<double>::infinity();
        else throw std::runtime_error(name + ": fill_value \"" + s + "\" is not a number, \"NaN\", \"Infinity\" or \"-Infinity\"");
        if (t.kind != 'f') throw std::runtime_error(name + ": fill_value \"" + s + "\" for the integer dtype " + t.str());
        return v;
    }
    if (!value.is_number()) throw std::runtime_error(name + ": fill_value is " + shortText(value) + ", not a number");
    const double v = value.get<double>();
    if (t.kind == 'f') return v;
    if (!value.is_number_integer())
        throw std::runtime_error(name + ": fill_value " + shortText(value) + " is not a whole number for dtype " + t.str());
    // The range of the stored integer type (exact for the 1-, 2- and 4-byte types).
    const int bits = 8 * t.size;
    const double lo = t.kind == 'u' ? 0.0 : -std::ldexp(1.0, bits - 1);
    const double hi = t.kind == 'u' ? std::ldexp(1.0, bits) - 1.0 : std::ldexp(1.0, bits - 1) - 1.0;
    if (value.is_number_unsigned() ? double(value.get<std::uint64_t>()) > hi : (v < lo || v > hi))
        throw std::runtime_error(name + ": fill_value " + shortText(value) + " is out of range for dtype " + t.str());
    return value.is_number_unsigned() ? double(value.get<std::uint64_t>()) : double(value.get<std::int64_t>());
}

std::vector<std::uint64_t> parseSizes(const Json& object, const char* key, const std::string& name)
{
    if (!object.contains(key)) throw std::runtime_error(name + ": no \"" + key + "\"");
    const Json& list = object[key];
    if (!list.is_array()) throw std::runtime_error(name + ": " + key + " is " + shortText(list) + ", not a list");
    if (list.empty()) throw std::runtime_error(name + ": " + key + " is empty (volren reads arrays of 1 to 32 dimensions)");
    if (list.size() > 32) throw std::runtime_error(name + ": " + key + " has " + std::to_string(list.size()) + " dimensions (at most 32)");
    std::vector<std::uint64_t> sizes;
    for (const Json& v : list) {
        const std::uint64_t n = zarrjson::unsignedInteger(v, std::string(key) + " entry", name);
        if (n == 0) throw std::runtime_error(name + ": " + key + " " + shortText(list) + " has a zero extent");
        sizes.push_back(n);
    }
    return sizes;
}

}  // namespace

std::string ZarrDataType::str() const
{
    return std::string(1, byteOrder) + kind + char('0' + size);
}

VoxelType ZarrDataType::voxelType() const
{
    if (kind == 'u' && size == 1) return VoxelType::UInt8;
    if (kind == 'i' && size == 1) return VoxelType::Int8;
    if (kind == 'u' && size == 2) return VoxelType::UInt16;
    if (kind == 'i' && size == 2) return VoxelType::Int16;
    return VoxelType::Float32;
}

bool ZarrDataType::converted() const
{
    return size > 2 && !(kind == 'f' && size == 4);
}

bool ZarrDataType::needsSwap() const
{
    return size > 1 && (byteOrder == '>') != (std::endian::native == std::endian::big);
}

std::uint64_t ZarrArrayMetadata::elementCount() const
{
    std::uint64_t n = 1;
    for (std::uint64_t s : shape) n *= s;
    return n;
}

std::uint64_t ZarrArrayMetadata::chunkElementCount() const
{
    std::uint64_t n = 1;
    for (std::uint64_t s : chunks) n *= s;
    return n;
}

std::uint64_t ZarrArrayMetadata::chunkBytes() const
{
    return chunkElementCount() * std::uint64_t(dtype.size);
}

std::vector<std::uint64_t> ZarrArrayMetadata::chunkGrid() const
{
    std::vector<std::uint64_t> grid(shape.size());
    for (std::size_t d = 0; d < shape.size(); ++d) grid[d] = shape[d] / chunks[d] + (shape[d] % chunks[d] ? 1 : 0);
    return grid;
}

std::string ZarrArrayMetadata::chunkKey(const std::vector<std::uint64_t>& index) const
{
    std::string key;
    for (std::size_t d = 0; d < index.size(); ++d) {
        if (d) key += separator;
        key += std::to_string(index[d]);
    }
    return key;
}

std::string ZarrArrayMetadata::toJson() const
{
    Json j;
    j["zarr_format"] = 2;
    j["shape"] = shape;
    j["chunks"] = chunks;
    j["dtype"] = dtype.str();
    if (compressor.id.empty()) j["compressor"] = nullptr;
    else if (compressor.id == "blosc")
        j["compressor"] = {{"id", "blosc"}, {"cname", compressor.cname}, {"clevel", compressor.level},
                           {"shuffle", compressor.shuffle}, {"blocksize", compressor.blocksize}};
    else j["compressor"] = {{"id", compressor.id}, {"level", compressor.level}};
    if (std::isnan(fillValue)) j["fill_value"] = "NaN";
    else if (std::isinf(fillValue)) j["fill_value"] = fillValue > 0 ? "Infinity" : "-Infinity";
    else if (dtype.kind == 'f') j["fill_value"] = fillValue;
    else j["fill_value"] = std::int64_t(fillValue);
    j["filters"] = nullptr;
    j["order"] = fortranOrder ? "F" : "C";
    j["dimension_separator"] = std::string(1, separator);
    return j.dump(4) + "\n";
}

ZarrArrayMetadata parseZarrArrayMetadata(const std::string& text, const std::string& name)
{
    const Json j = zarrjson::parse(text, name);
    if (!j.is_object()) throw std::runtime_error(name + ": not a JSON object");
    if (!j.contains("zarr_format")) throw std::runtime_error(name + ": no \"zarr_format\" (not zarr v2 array metadata)");
    if (j["zarr_format"] != 2)
        throw std::runtime_error(name + ": zarr_format " + shortText(j["zarr_format"]) + " (volren reads zarr format 2)");
    ZarrArrayMetadata m;
    m.shape = parseSizes(j, "shape", name);
    m.chunks = parseSizes(j, "chunks", name);
    if (m.chunks.size() != m.shape.size())
        throw std::runtime_error(name + ": chunks " + listText(m.chunks) + " and shape " + listText(m.shape) +
                                 " have different numbers of dimensions");
    if (!j.contains("dtype")) throw std::runtime_error(name + ": no \"dtype\"");
    m.dtype = parseDataType(j["dtype"], name);
    m.compressor = parseCompressor(j.contains("compressor") ? j["compressor"] : Json(), name);
    if (j.contains("filters") && !j["filters"].is_null()) {
        const Json& filters = j["filters"];
        if (!filters.is_array()) throw std::runtime_error(name + ": filters is " + shortText(filters) + ", not null or a list");
        if (!filters.empty()) {
            const Json& first = filters.front();
            const std::string id = first.is_object() && first.contains("id") ? shortText(first["id"]) : shortText(first);
            throw std::runtime_error(name + ": filters are not supported (filter " + id + ")");
        }
    }
    const Json order = j.contains("order") ? j["order"] : Json("C");
    if (order != "C" && order != "F") throw std::runtime_error(name + ": order " + shortText(order) + " is not \"C\" or \"F\"");
    m.fortranOrder = order == "F";
    m.fillValue = parseFillValue(j.contains("fill_value") ? j["fill_value"] : Json(), m.dtype, name);
    if (j.contains("dimension_separator") && !j["dimension_separator"].is_null()) {
        const Json& sep = j["dimension_separator"];
        if (sep != "." && sep != "/")
            throw std::runtime_error(name + ": dimension_separator " + shortText(sep) + " is not \".\" or \"/\"");
        m.separator = sep.get<std::string>()[0];
    }

    // Sizes: the whole array's bytes must be countable, a chunk's bytes within the limit.
    std::uint64_t elements = 1, chunkElements = 1;
    for (std::size_t d = 0; d < m.shape.size(); ++d) {
        if (!zarrjson::checkedMultiply(elements, m.shape[d], elements))
            throw std::runtime_error(name + ": shape " + listText(m.shape) + " overflows (more than 2^64 elements)");
        if (!zarrjson::checkedMultiply(chunkElements, m.chunks[d], chunkElements))
            throw std::runtime_error(name + ": chunks " + listText(m.chunks) + " overflow (more than 2^64 elements per chunk)");
    }
    std::uint64_t bytes = 0, chunkBytes = 0;
    if (!zarrjson::checkedMultiply(elements, std::uint64_t(m.dtype.size), bytes))
        throw std::runtime_error(name + ": shape " + listText(m.shape) + " of " + m.dtype.str() + " overflows (more than 2^64 bytes)");
    if (!zarrjson::checkedMultiply(chunkElements, std::uint64_t(m.dtype.size), chunkBytes) || chunkBytes > ZarrArrayMetadata::maxChunkBytes)
        throw std::runtime_error(name + ": chunks " + listText(m.chunks) + " of " + m.dtype.str() +
                                 " are over volren's limit of 512 MiB per chunk");
    return m;
}

}  // namespace volren
