#include "NrrdWriter.h"

#include <zlib.h>

#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace volren::nrrd {

namespace {

const char* nrrdTypeName(VoxelType type)
{
    switch (type) {
    case VoxelType::UInt8: return "uint8";
    case VoxelType::Int8: return "int8";
    case VoxelType::UInt16: return "uint16";
    case VoxelType::Int16: return "int16";
    case VoxelType::Float32: return "float";
    }
    return "?";
}

struct FileCloser
{
    void operator()(std::FILE* f) const { std::fclose(f); }
};

/// Writes `size` bytes through a gzip deflate stream into `out`.
void writeGzip(std::FILE* out, const std::uint8_t* data, std::size_t size, const std::string& path)
{
    z_stream zs{};
    if (deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw std::runtime_error(path + ": cannot start gzip compression");
    std::vector<unsigned char> buffer(std::size_t(1) << 20);
    std::size_t done = 0;
    int ret = Z_OK;
    do {
        const std::size_t n = std::min<std::size_t>(size - done, std::size_t(1) << 30);
        zs.next_in = const_cast<std::uint8_t*>(data + done);
        zs.avail_in = unsigned(n);
        done += n;
        const int flush = done == size ? Z_FINISH : Z_NO_FLUSH;
        do {
            zs.next_out = buffer.data();
            zs.avail_out = unsigned(buffer.size());
            ret = deflate(&zs, flush);
            const std::size_t have = buffer.size() - zs.avail_out;
            if (std::fwrite(buffer.data(), 1, have, out) != have) {
                deflateEnd(&zs);
                throw std::runtime_error(path + ": write failed: " + std::strerror(errno));
            }
        } while (zs.avail_out == 0);
    } while (done < size);
    deflateEnd(&zs);
    if (ret != Z_STREAM_END) throw std::runtime_error(path + ": gzip compression did not finish");
}

}  // namespace

void writeNrrd(const Volume& volume, const std::string& path, bool gzip)
{
    if (volume.frames() > 1)
        throw std::runtime_error(path + ": the NRRD writer does not write time series (" + std::to_string(volume.frames()) + " time points)");
    if (volume.totalVoxelCount() == 0) throw std::runtime_error(path + ": the volume is empty");
    const osg::Vec3i& d = volume.dims();
    const osg::Vec3d& s = volume.spacing();
    const int channels = volume.channels();
    std::ostringstream header;
    header << std::setprecision(17);
    header << "NRRD0004\n# written by volren\ntype: " << nrrdTypeName(volume.type()) << "\n";
    header << "dimension: " << (channels > 1 ? 4 : 3) << "\nsizes:";
    if (channels > 1) header << " " << channels;
    header << " " << d.x() << " " << d.y() << " " << d.z() << "\nspacings:";
    if (channels > 1) header << " nan";
    header << " " << s.x() << " " << s.y() << " " << s.z() << "\nkinds:";
    if (channels > 1) header << " vector";
    header << " domain domain domain\n";
    if (voxelSize(volume.type()) > 1) header << "endian: " << ((std::endian::native == std::endian::big) ? "big" : "little") << "\n";
    header << "encoding: " << (gzip ? "gzip" : "raw") << "\n";
    if (volume.rescaleSlope() != 1.0 || volume.rescaleIntercept() != 0.0)
        header << "volren_rescale:=" << volume.rescaleSlope() << " " << volume.rescaleIntercept() << "\n";
    header << "\n";

    // NRRD interleaves channels per voxel; the Volume keeps one block per channel.
    const std::size_t width = voxelSize(volume.type());
    const std::uint8_t* payload = volume.data();
    std::vector<std::uint8_t> interleaved;
    if (channels > 1) {
        const std::size_t n = volume.voxelCount(), c = std::size_t(channels);
        interleaved.resize(volume.byteSize());
        for (std::size_t ch = 0; ch < c; ++ch) {
            const std::uint8_t* in = volume.block(int(ch));
            for (std::size_t v = 0; v < n; ++v) std::memcpy(interleaved.data() + (v * c + ch) * width, in + v * width, width);
        }
        payload = interleaved.data();
    }

    errno = 0;
    std::unique_ptr<std::FILE, FileCloser> out(std::fopen(path.c_str(), "wb"));
    if (!out) throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(errno));
    const std::string text = header.str();
    if (std::fwrite(text.data(), 1, text.size(), out.get()) != text.size())
        throw std::runtime_error(path + ": write failed: " + std::strerror(errno));
    if (gzip) writeGzip(out.get(), payload, volume.byteSize(), path);
    else if (std::fwrite(payload, 1, volume.byteSize(), out.get()) != volume.byteSize())
        throw std::runtime_error(path + ": write failed: " + std::strerror(errno));
    if (std::fclose(out.release()) != 0) throw std::runtime_error(path + ": write failed: " + std::strerror(errno));
}

}  // namespace volren::nrrd
