#include "DicomSeriesReader.h"

#include <volume_model/LengthUnit.h>
#include <volume_model/LoadProgress.h>

#include <osg/Matrixd>
#include <osg/Notify>
#include <osg/ValueObject>

#include <gdcmImageReader.h>
#include <gdcmReader.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>

namespace volren::dicom {

namespace {

/// How the voxels of the first slice are stored; every other slice must match.
struct Layout
{
    unsigned int columns = 0, rows = 0, frames = 1;
    unsigned short bitsAllocated = 0, bitsStored = 0, highBit = 0, signedness = 0;
    std::size_t bytesPerVoxel() const { return bitsAllocated / 8u; }
    std::size_t sliceBytes() const { return std::size_t(columns) * rows * frames * bytesPerVoxel(); }
    bool operator==(const Layout& o) const
    {
        return columns == o.columns && rows == o.rows && frames == o.frames && bitsAllocated == o.bitsAllocated &&
               bitsStored == o.bitsStored && highBit == o.highBit && signedness == o.signedness;
    }
};

VoxelType typeOf(const Layout& l, const std::string& file)
{
    switch (l.bitsAllocated) {
    case 8: return l.signedness ? VoxelType::Int8 : VoxelType::UInt8;
    case 16: return l.signedness ? VoxelType::Int16 : VoxelType::UInt16;
    case 32: return VoxelType::Float32;
    default:
        throw std::runtime_error(file + ": unsupported DICOM BitsAllocated " + std::to_string(l.bitsAllocated) +
                                 " (8, 16 or 32 are read)");
    }
}

/// Clears the bits above BitsStored (unsigned) or sign-extends from them (signed).
template <typename T>
void normaliseBits(T* values, std::size_t count, const Layout& l)
{
    const unsigned width = sizeof(T) * 8u;
    if (l.bitsStored == 0 || l.bitsStored >= width || l.highBit + 1u != l.bitsStored) return;
    const unsigned shift = width - l.bitsStored;
    using U = std::make_unsigned_t<T>;
    using S = std::make_signed_t<T>;
    for (std::size_t i = 0; i < count; ++i) {
        const U u = U(U(values[i]) << shift);
        values[i] = l.signedness ? T(S(u) >> shift) : T(u >> shift);
    }
}

/// Copies (and for 32-bit integers widens to float) one decoded slice into `dst`.
void storeSlice(std::vector<char>& buffer, std::uint8_t* dst, std::size_t count, const Layout& l, double slope,
                double intercept, bool applyRescale)
{
    if (l.bitsAllocated == 8) {
        if (l.signedness) normaliseBits(reinterpret_cast<std::int8_t*>(buffer.data()), count, l);
        else normaliseBits(reinterpret_cast<std::uint8_t*>(buffer.data()), count, l);
    } else if (l.bitsAllocated == 16) {
        if (l.signedness) normaliseBits(reinterpret_cast<std::int16_t*>(buffer.data()), count, l);
        else normaliseBits(reinterpret_cast<std::uint16_t*>(buffer.data()), count, l);
    }
    if (!applyRescale && l.bitsAllocated != 32) {
        std::memcpy(dst, buffer.data(), count * l.bytesPerVoxel());
        return;
    }
    // Float32 output: 32-bit integers, or every type when slices have different rescales.
    for (std::size_t i = 0; i < count; ++i) {
        double v = 0.0;
        const char* p = buffer.data() + i * l.bytesPerVoxel();
        switch (l.bitsAllocated) {
        case 8: v = l.signedness ? double(std::int8_t(*p)) : double(std::uint8_t(*p)); break;
        case 16: {
            std::uint16_t u;
            std::memcpy(&u, p, 2);
            v = l.signedness ? double(std::int16_t(u)) : double(u);
            break;
        }
        default: {
            std::uint32_t u;
            std::memcpy(&u, p, 4);
            v = l.signedness ? double(std::int32_t(u)) : double(u);
            break;
        }
        }
        const float f = float(applyRescale ? v * slope + intercept : v);
        std::memcpy(dst + i * sizeof(float), &f, sizeof(float));
    }
}

/// Bytes from the start of the PixelData value to the end of `file` (uncompressed files):
/// GDCM pads a short or cut PixelData with a warning only, so the reader checks it.
std::uint64_t nativePixelBytesInFile(const std::string& file)
{
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file + ": cannot open for reading");
    gdcm::Reader reader;
    reader.SetStream(in);
    const gdcm::Tag pixelData(0x7fe0, 0x0010);
    std::set<gdcm::Tag> skip{pixelData};  // stop with the stream at the start of its value
    if (!reader.ReadUpToTag(pixelData, skip)) throw std::runtime_error(file + ": GDCM cannot read the header");
    const std::streamoff start = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streamoff end = in.tellg();
    return start >= 0 && end >= start ? std::uint64_t(end - start) : 0;
}

}  // namespace

osg::ref_ptr<Volume> readSeries(const SliceOrder& order, const std::string& name, const osgDB::Options* options)
{
    const std::size_t fileCount = order.slices.size();
    if (fileCount == 0) throw std::runtime_error(name + ": no DICOM slices");
    if (fileCount > 1)
        for (const DicomSlice& s : order.slices)
            if (s.frames > 1)
                throw std::runtime_error(s.file + ": multi-frame file (" + std::to_string(s.frames) +
                                         " frames) in a series of several files is not supported");

    osg::ref_ptr<Volume> volume = new Volume;
    Layout first;
    VoxelType type = VoxelType::UInt16;
    osg::Vec3d spacing(1, 1, 1);
    double slope0 = 1.0, intercept0 = 0.0;
    bool mixedRescale = false;
    std::vector<std::pair<double, double>> rescales;
    std::vector<char> buffer;

    for (std::size_t n = 0; n < fileCount; ++n) {
        const std::string& file = order.slices[n].file;
        gdcm::ImageReader reader;
        reader.SetFileName(file.c_str());
        if (!reader.Read()) throw std::runtime_error(file + ": GDCM cannot read this file as a DICOM image");
        const gdcm::Image& image = reader.GetImage();
        const gdcm::PixelFormat& pf = image.GetPixelFormat();
        if (pf.GetSamplesPerPixel() != 1)
            throw std::runtime_error(file + ": colour DICOM images (" + std::to_string(pf.GetSamplesPerPixel()) +
                                     " samples per pixel) are not supported");
        Layout layout;
        layout.columns = image.GetDimension(0);
        layout.rows = image.GetDimension(1);
        layout.frames = image.GetNumberOfDimensions() > 2 ? std::max(1u, image.GetDimension(2)) : 1u;
        layout.bitsAllocated = pf.GetBitsAllocated();
        layout.bitsStored = pf.GetBitsStored();
        layout.highBit = pf.GetHighBit();
        layout.signedness = pf.GetPixelRepresentation();

        if (n == 0) {
            first = layout;
            type = typeOf(layout, file);
            const osg::Vec3i dims(int(layout.columns), int(layout.rows), int(layout.frames * fileCount));
            if (layout.columns > 1u << 30 || layout.rows > 1u << 30 || layout.frames > 1u << 30)
                throw std::runtime_error(file + ": implausible DICOM image size");
            try {
                volume->allocate(type, dims);
            } catch (const std::exception& e) {
                throw std::runtime_error(name + ": " + e.what());
            }
            for (int a = 0; a < 2; ++a) {
                const double s = image.GetSpacing(a);
                if (s > 0.0 && std::isfinite(s)) spacing[a] = s;
                else OSG_WARN << file << ": pixel spacing " << s << " is not positive; using 1" << std::endl;
            }
            if (order.sliceSpacing > 0.0) {
                spacing[2] = order.sliceSpacing;
            } else if (image.GetSpacing(2) > 0.0 && std::isfinite(image.GetSpacing(2))) {
                spacing[2] = image.GetSpacing(2);
            }
            if (image.GetPhotometricInterpretation() == gdcm::PhotometricInterpretation::MONOCHROME1)
                OSG_WARN << file << ": MONOCHROME1 (white is low); values are kept as stored" << std::endl;
        } else if (!(layout == first)) {
            const bool sizeDiffers = layout.columns != first.columns || layout.rows != first.rows;
            throw std::runtime_error(
                file + (sizeDiffers ? ": mixed slice sizes in the series: " + std::to_string(layout.columns) + "x" +
                                          std::to_string(layout.rows) + ", the first slice is " +
                                          std::to_string(first.columns) + "x" + std::to_string(first.rows)
                                    : std::string(": pixel format differs from the first slice of the series")));
        }
        const double slope = std::isfinite(image.GetSlope()) && image.GetSlope() != 0.0 ? image.GetSlope() : 1.0;
        const double intercept = std::isfinite(image.GetIntercept()) ? image.GetIntercept() : 0.0;
        if (n == 0) slope0 = slope, intercept0 = intercept;
        else if (slope != slope0 || intercept != intercept0) mixedRescale = true;
        rescales.emplace_back(slope, intercept);

        if (image.GetBufferLength() != first.sliceBytes())
            throw std::runtime_error(file + ": decoded pixel data has " + std::to_string(image.GetBufferLength()) +
                                     " bytes, expected " + std::to_string(first.sliceBytes()));
        const gdcm::TransferSyntax& syntax = reader.GetFile().GetHeader().GetDataSetTransferSyntax();
        if (!syntax.IsEncapsulated()) {
            const std::uint64_t available = nativePixelBytesInFile(file);
            if (available < first.sliceBytes())
                throw std::runtime_error(file + ": truncated: pixel data needs " + std::to_string(first.sliceBytes()) +
                                         " bytes, the file holds " + std::to_string(available));
        }
        buffer.resize(first.sliceBytes());
        if (!image.GetBuffer(buffer.data())) {
            const char* tsName = gdcm::TransferSyntax::GetTSString(syntax);
            throw std::runtime_error(file + ": cannot decode the pixel data (transfer syntax " +
                                     std::string(tsName ? tsName : "unknown") + ")");
        }
        const std::size_t count = std::size_t(first.columns) * first.rows * first.frames;
        storeSlice(buffer, volume->data() + n * count * voxelSize(type), count, first, slope, intercept, false);
        if (!reportLoadProgress(options, double(n + 1), double(fileCount)))
            throw std::runtime_error(name + ": cancelled");
    }

    if (mixedRescale) {
        // Slices with different RescaleSlope/Intercept: store data values as float32.
        OSG_NOTICE << name << ": slices have different rescale slopes/intercepts; stored as float32 data values"
                   << std::endl;
        const std::size_t count = std::size_t(first.columns) * first.rows * first.frames;
        const std::size_t inBytes = voxelSize(type);
        std::vector<std::uint8_t> floats(count * fileCount * sizeof(float));
        for (std::size_t n = 0; n < fileCount; ++n) {
            if (type == VoxelType::Float32) {  // 32-bit integers, already widened
                for (std::size_t i = 0; i < count; ++i) {
                    float f;
                    std::memcpy(&f, volume->data() + (n * count + i) * 4, 4);
                    f = float(f * rescales[n].first + rescales[n].second);
                    std::memcpy(floats.data() + (n * count + i) * 4, &f, 4);
                }
                continue;
            }
            buffer.assign(reinterpret_cast<const char*>(volume->data() + n * count * inBytes),
                          reinterpret_cast<const char*>(volume->data() + (n + 1) * count * inBytes));
            storeSlice(buffer, floats.data() + n * count * sizeof(float), count, first, rescales[n].first,
                       rescales[n].second, true);
        }
        const osg::Vec3i dims = volume->dims();
        volume->assign(VoxelType::Float32, dims, std::move(floats));
        slope0 = 1.0, intercept0 = 0.0;
    } else if (type == VoxelType::Float32) {
        OSG_NOTICE << name << ": 32-bit integer voxels stored as float32" << std::endl;
    }

    volume->setSpacing(spacing);
    volume->setUserValue(spacingUnitKey, std::string("mm"));  // DICOM's Pixel Spacing and positions are in mm
    volume->setRescale(slope0, intercept0);
    volume->sourceFile = name;
    volume->setName(name);
    const DicomSlice& s0 = order.slices.front();
    if (s0.hasPosition && s0.hasOrientation) {
        const osg::Vec3d r = s0.rowDirection * spacing.x(), c = s0.columnDirection * spacing.y(),
                         k = order.normal * spacing.z();
        const osg::Matrixd toWorld(r.x(), r.y(), r.z(), 0, c.x(), c.y(), c.z(), 0, k.x(), k.y(), k.z(), 0,
                                   s0.position.x(), s0.position.y(), s0.position.z(), 1);
        volume->setUserValue(voxelToWorldKey, toWorld);
    }
    OSG_INFO << name << ": DICOM series of " << fileCount << " files, " << volume->dims().x() << "x"
             << volume->dims().y() << "x" << volume->dims().z() << " " << voxelTypeName(volume->type()) << std::endl;
    return volume;
}

}  // namespace volren::dicom
