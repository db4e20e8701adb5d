#include "TiffPage.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace volren::tiff {

namespace {

std::string pageName(const TiffFile& file, std::size_t page)
{
    return file.path() + ": page " + std::to_string(page);
}

const char* sampleFormatName(std::uint16_t format)
{
    switch (format) {
    case SAMPLEFORMAT_UINT: return "unsigned integer";
    case SAMPLEFORMAT_INT: return "signed integer";
    case SAMPLEFORMAT_IEEEFP: return "floating point";
    case SAMPLEFORMAT_VOID: return "untyped";
    case SAMPLEFORMAT_COMPLEXINT: return "complex integer";
    case SAMPLEFORMAT_COMPLEXIEEEFP: return "complex floating point";
    default: return "unknown";
    }
}

/// Copies `rows` x `cols` pixels of `spp` interleaved samples (`bytes` each) from a decoded
/// strip/tile (`srcStride` bytes per row) into the planes at (x0, y0); `firstPlane` is the
/// plane of the first sample (separate planar files have one sample per strip).
void scatter(const std::uint8_t* src, std::size_t srcStride, std::uint32_t x0, std::uint32_t y0, std::uint32_t cols,
             std::uint32_t rows, std::size_t spp, std::size_t firstPlane, std::size_t bytes, const PageFormat& format,
             std::uint8_t* planes)
{
    const std::size_t planeBytes = std::size_t(format.width) * format.height * bytes;
    for (std::uint32_t r = 0; r < rows; ++r) {
        const std::uint8_t* in = src + r * srcStride;
        const std::size_t rowStart = (std::size_t(y0 + r) * format.width + x0) * bytes;
        if (spp == 1) {
            std::memcpy(planes + firstPlane * planeBytes + rowStart, in, cols * bytes);
            continue;
        }
        for (std::uint32_t c = 0; c < cols; ++c)
            for (std::size_t s = 0; s < spp; ++s)
                std::memcpy(planes + (firstPlane + s) * planeBytes + rowStart + c * bytes, in + (c * spp + s) * bytes, bytes);
    }
}

/// Converts 32-bit integers (in place, same width) to float.
void widen(std::uint8_t* data, std::size_t count, bool isSigned)
{
    for (std::size_t i = 0; i < count; ++i) {
        float f;
        if (isSigned) {
            std::int32_t v;
            std::memcpy(&v, data + 4 * i, 4);
            f = float(v);
        } else {
            std::uint32_t v;
            std::memcpy(&v, data + 4 * i, 4);
            f = float(v);
        }
        std::memcpy(data + 4 * i, &f, 4);
    }
}

}  // namespace

std::string PageFormat::describe() const
{
    return std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(bitsPerSample) + "-bit " +
           sampleFormatName(sampleFormat) + " x " + std::to_string(samplesPerPixel) + " sample(s)";
}

bool PageFormat::sameLayout(const PageFormat& other) const
{
    return width == other.width && height == other.height && bitsPerSample == other.bitsPerSample &&
           samplesPerPixel == other.samplesPerPixel && type == other.type;
}

PageFormat readPageFormat(TiffFile& file, std::size_t page)
{
    TIFF* tif = file.handle();
    PageFormat f;
    if (!TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &f.width) || !TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &f.height))
        file.fail("page " + std::to_string(page) + ": no image size");
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &f.bitsPerSample);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &f.samplesPerPixel);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &f.sampleFormat);
    TIFFGetFieldDefaulted(tif, TIFFTAG_PLANARCONFIG, &f.planar);
    TIFFGetFieldDefaulted(tif, TIFFTAG_COMPRESSION, &f.compression);
    if (!TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &f.photometric)) f.photometric = PHOTOMETRIC_MINISBLACK;
    f.tiled = TIFFIsTiled(tif) != 0;
    const std::string where = pageName(file, page);
    if (f.width == 0 || f.height == 0) throw std::runtime_error(where + ": empty image (" + f.describe() + ")");
    if (f.samplesPerPixel == 0 || f.samplesPerPixel > 16)
        throw std::runtime_error(where + ": unsupported samples per pixel " + std::to_string(f.samplesPerPixel));
    if (f.bitsPerSample != 8 && f.bitsPerSample != 16 && f.bitsPerSample != 32)
        throw std::runtime_error(where + ": unsupported bits per sample " + std::to_string(f.bitsPerSample) +
                                 " (only 8, 16 and 32)");
    const bool isSigned = f.sampleFormat == SAMPLEFORMAT_INT;
    switch (f.sampleFormat) {
    case SAMPLEFORMAT_UINT: case SAMPLEFORMAT_VOID: case SAMPLEFORMAT_INT:
        if (f.bitsPerSample == 8) f.type = isSigned ? VoxelType::Int8 : VoxelType::UInt8;
        else if (f.bitsPerSample == 16) f.type = isSigned ? VoxelType::Int16 : VoxelType::UInt16;
        else f.type = VoxelType::Float32, f.widenToFloat = true;
        break;
    case SAMPLEFORMAT_IEEEFP:
        if (f.bitsPerSample != 32)
            throw std::runtime_error(where + ": unsupported " + std::to_string(f.bitsPerSample) +
                                     "-bit floating point samples (only 32-bit)");
        f.type = VoxelType::Float32;
        break;
    default:
        throw std::runtime_error(where + ": unsupported sample format " + std::to_string(f.sampleFormat) + " (" +
                                 sampleFormatName(f.sampleFormat) + ")");
    }
    if (f.photometric == PHOTOMETRIC_YCBCR) {
        if (f.compression != COMPRESSION_JPEG)
            throw std::runtime_error(where + ": YCbCr pages are only supported with JPEG compression");
        TIFFSetField(tif, TIFFTAG_JPEGCOLORMODE, JPEGCOLORMODE_RGB);  // libtiff converts to RGB
    }
    if (!TIFFIsCODECConfigured(f.compression))
        throw std::runtime_error(where + ": compression scheme " + std::to_string(f.compression) +
                                 " is not supported by this libtiff");
    return f;
}

void checkPageExtent(TiffFile& file, const PageFormat& format, std::size_t page)
{
    TIFF* tif = file.handle();
    const std::uint32_t count = format.tiled ? TIFFNumberOfTiles(tif) : TIFFNumberOfStrips(tif);
    if (count == 0) throw std::runtime_error(pageName(file, page) + ": no image data (zero strips)");
    for (std::uint32_t i = 0; i < count; ++i) {
        int error = 0;
        const std::uint64_t offset = TIFFGetStrileOffsetWithErr(tif, i, &error);
        const std::uint64_t bytes = error ? 0 : TIFFGetStrileByteCountWithErr(tif, i, &error);
        if (error) file.fail("page " + std::to_string(page) + ": cannot read the strip/tile table");
        if (offset > file.fileSize() || bytes > file.fileSize() - offset)
            throw std::runtime_error(pageName(file, page) + ": truncated file: " + (format.tiled ? "tile " : "strip ") +
                                     std::to_string(i) + " ends at byte " + std::to_string(offset + bytes) +
                                     " but the file has " + std::to_string(file.fileSize()) + " bytes");
    }
}

void readPageSamples(TiffFile& file, const PageFormat& format, std::size_t page, std::vector<std::uint8_t>& planes)
{
    TIFF* tif = file.handle();
    const std::size_t bytes = format.bitsPerSample / 8;
    const std::size_t spp = format.samplesPerPixel;
    const bool separate = format.planar == PLANARCONFIG_SEPARATE && spp > 1;
    const std::size_t samplesPerChunk = separate ? 1 : spp;
    planes.assign(std::size_t(format.width) * format.height * spp * bytes, 0);
    const std::string what = "page " + std::to_string(page);

    if (format.tiled) {
        std::uint32_t tw = 0, th = 0;
        TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(tif, TIFFTAG_TILELENGTH, &th);
        if (tw == 0 || th == 0) file.fail(what + ": invalid tile size");
        std::vector<std::uint8_t> tile(std::size_t(TIFFTileSize(tif)));
        const std::size_t stride = std::size_t(tw) * samplesPerChunk * bytes;
        if (tile.size() < stride * th) file.fail(what + ": inconsistent tile size");
        for (std::size_t s = 0; s < (separate ? spp : 1); ++s)
            for (std::uint32_t y = 0; y < format.height; y += th)
                for (std::uint32_t x = 0; x < format.width; x += tw) {
                    const std::uint32_t index = TIFFComputeTile(tif, x, y, 0, std::uint16_t(s));
                    if (TIFFReadEncodedTile(tif, index, tile.data(), tmsize_t(tile.size())) < 0)
                        file.fail(what + ": cannot decode tile " + std::to_string(index));
                    scatter(tile.data(), stride, x, y, std::min(tw, format.width - x), std::min(th, format.height - y),
                            samplesPerChunk, s, bytes, format, planes.data());
                }
    } else {
        std::uint32_t rowsPerStrip = 0;
        TIFFGetFieldDefaulted(tif, TIFFTAG_ROWSPERSTRIP, &rowsPerStrip);
        rowsPerStrip = std::min(std::max<std::uint32_t>(rowsPerStrip, 1), format.height);
        const std::size_t stride = std::size_t(format.width) * samplesPerChunk * bytes;
        std::vector<std::uint8_t> strip(stride * rowsPerStrip);
        for (std::size_t s = 0; s < (separate ? spp : 1); ++s)
            for (std::uint32_t y = 0; y < format.height; y += rowsPerStrip) {
                const std::uint32_t rows = std::min(rowsPerStrip, format.height - y);
                const std::uint32_t index = TIFFComputeStrip(tif, y, std::uint16_t(s));
                const tmsize_t got = TIFFReadEncodedStrip(tif, index, strip.data(), tmsize_t(stride * rows));
                if (got < 0) file.fail(what + ": cannot decode strip " + std::to_string(index));
                if (std::size_t(got) < stride * rows)
                    throw std::runtime_error(file.path() + ": " + what + ": truncated strip " + std::to_string(index) +
                                             " (" + std::to_string(got) + " of " + std::to_string(stride * rows) + " bytes)");
                scatter(strip.data(), stride, 0, y, format.width, rows, samplesPerChunk, s, bytes, format, planes.data());
            }
    }
    if (format.widenToFloat) widen(planes.data(), planes.size() / 4, format.sampleFormat == SAMPLEFORMAT_INT);
}

}  // namespace volren::tiff
