#include "Payload.h"

#include <volume_model/LoadProgress.h>

#include <osgDB/FileUtils>

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace volren::rawvolume {

namespace {

constexpr std::size_t chunkSize = std::size_t(1) << 20;  // progress is reported per chunk

struct FileCloser
{
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

/// Progress over the whole payload; throws "name: cancelled" when the callback says stop.
struct Progress
{
    const osgDB::Options* options;
    const std::string& name;
    double total;
    double done = 0.0;

    void advance(std::size_t n)
    {
        done += double(n);
        if (!reportLoadProgress(options, done, total)) throw std::runtime_error(name + ": cancelled");
    }
};

std::runtime_error failure(const std::string& name, const std::string& why) { return std::runtime_error(name + ": " + why); }

/// Skips `lines` text lines at the current position of `f`.
void skipLines(std::FILE* f, std::uint64_t lines, const std::string& name, const std::string& path)
{
    for (std::uint64_t i = 0; i < lines; ++i) {
        int c;
        while ((c = std::fgetc(f)) != EOF && c != '\n') {
        }
        if (c == EOF) throw failure(name, "truncated: data file " + path + " ends within the " + std::to_string(lines) + " skipped lines");
    }
}

/// First byte of the voxels of an uncompressed part whose skipped lines end at `start`; checks
/// that exactly `bytes` follow it.
std::uint64_t uncompressedBegin(std::uint64_t start, std::uint64_t fileSize, const PayloadPart& part, std::uint64_t bytes,
                                const std::string& name)
{
    std::uint64_t begin = start;
    if (part.byteSkip == -1) {
        if (fileSize < bytes)
            throw failure(name, "truncated: data file " + part.path + " has " + std::to_string(fileSize) +
                                    " bytes, the header needs " + std::to_string(bytes));
        begin = fileSize - bytes;
    } else {
        begin += std::uint64_t(part.byteSkip);
    }
    const std::uint64_t available = fileSize > begin ? fileSize - begin : 0;
    if (available < bytes)
        throw failure(name, "truncated: data file " + part.path + " holds " + std::to_string(available) +
                                " bytes of voxel data, the header needs " + std::to_string(bytes));
    if (available > bytes)
        throw failure(name, "size mismatch: data file " + part.path + " holds " + std::to_string(available) +
                                " bytes of voxel data, the header implies " + std::to_string(bytes));
    return begin;
}

void readUncompressed(std::FILE* f, std::uint64_t start, std::uint64_t fileSize, const PayloadPart& part,
                      std::uint8_t* dst, std::uint64_t bytes, const std::string& name, Progress& progress)
{
    const std::uint64_t begin = uncompressedBegin(start, fileSize, part, bytes, name);
    if (fseeko(f, off_t(begin), SEEK_SET) != 0) throw failure(name, "cannot seek in data file " + part.path);
    std::uint64_t done = 0;
    while (done < bytes) {
        const std::size_t n = std::size_t(std::min<std::uint64_t>(bytes - done, chunkSize));
        const std::size_t got = std::fread(dst + done, 1, n, f);
        if (got != n)
            throw failure(name, std::ferror(f) ? "read error in data file " + part.path + ": " + std::strerror(errno)
                                               : "truncated: data file " + part.path + " ends after " +
                                                     std::to_string(done + got) + " of " + std::to_string(bytes) + " bytes");
        done += n;
        progress.advance(n);
    }
}

void readCompressed(std::FILE* f, std::uint64_t fileSize, const PayloadPart& part, std::uint8_t* dst, std::uint64_t bytes,
                    const std::string& name, Progress& progress)
{
    if (part.byteSkip != 0) throw failure(name, "a byte skip with compressed data is not supported");
    const std::uint64_t start = std::uint64_t(ftello(f));
    std::uint64_t inputLeft = fileSize > start ? fileSize - start : 0;
    if (part.compressedSize) {
        if (part.compressedSize > inputLeft)
            throw failure(name, "truncated: data file " + part.path + " holds " + std::to_string(inputLeft) +
                                    " bytes of compressed data, the header says " + std::to_string(part.compressedSize));
        inputLeft = part.compressedSize;
    }
    z_stream zs{};
    if (inflateInit2(&zs, 15 + 32) != Z_OK) throw failure(name, "cannot start zlib");
    struct End
    {
        z_stream* zs;
        ~End() { inflateEnd(zs); }
    } end{&zs};
    std::vector<unsigned char> input(std::size_t(1) << 20);
    const auto refill = [&] {
        const std::size_t want = std::size_t(std::min<std::uint64_t>(inputLeft, input.size()));
        const std::size_t got = want ? std::fread(input.data(), 1, want, f) : 0;
        if (got != want && std::ferror(f)) throw failure(name, "read error in data file " + part.path + ": " + std::strerror(errno));
        inputLeft -= got;
        zs.next_in = input.data();
        zs.avail_in = unsigned(got);
        return got > 0;
    };
    const auto corrupt = [&](int code) {
        return failure(name, "corrupt compressed data in " + part.path + ": " +
                                 (zs.msg ? std::string(zs.msg) : "zlib error " + std::to_string(code)));
    };
    std::uint64_t done = 0;
    bool streamEnded = false;
    while (done < bytes) {
        const std::size_t n = std::size_t(std::min<std::uint64_t>(bytes - done, chunkSize));
        zs.next_out = dst + done;
        zs.avail_out = unsigned(n);
        while (zs.avail_out > 0) {
            if (zs.avail_in == 0 && !refill())
                throw failure(name, "truncated: compressed data in " + part.path + " end after " +
                                        std::to_string(done + (n - zs.avail_out)) + " of " + std::to_string(bytes) + " bytes");
            if (streamEnded) {  // another gzip member follows
                inflateReset(&zs);
                streamEnded = false;
            }
            const int ret = inflate(&zs, Z_NO_FLUSH);
            if (ret == Z_STREAM_END) {
                streamEnded = true;
                if (zs.avail_in == 0 && inputLeft == 0 && zs.avail_out > 0)
                    throw failure(name, "truncated: compressed data in " + part.path + " decode to " +
                                            std::to_string(done + (n - zs.avail_out)) + " bytes, the header needs " +
                                            std::to_string(bytes));
            } else if (ret != Z_OK && ret != Z_BUF_ERROR) {
                throw corrupt(ret);
            }
        }
        done += n;
        progress.advance(n);
    }
    // The stream must end here: more output is a size mismatch, a missing end (checksum) is damage.
    unsigned char extra = 0;
    while (!streamEnded) {
        if (zs.avail_in == 0 && !refill())
            throw failure(name, "truncated: compressed data in " + part.path + " stop before the end of the stream");
        zs.next_out = &extra;
        zs.avail_out = 1;
        const int ret = inflate(&zs, Z_NO_FLUSH);
        if (zs.avail_out == 0)
            throw failure(name, "size mismatch: compressed data in " + part.path + " hold more than the " +
                                    std::to_string(bytes) + " bytes the header implies");
        if (ret == Z_STREAM_END) streamEnded = true;
        else if (ret != Z_OK && ret != Z_BUF_ERROR) throw corrupt(ret);
    }
}

/// Opens the data file of `part` and gives its size; throws when it cannot be read or is
/// shorter than the part's offset.
File openPart(const PayloadPart& part, const std::string& name, std::uint64_t& fileSize)
{
    if (osgDB::fileType(part.path) == osgDB::DIRECTORY) throw failure(name, "data file " + part.path + " is a directory");
    errno = 0;
    File f(std::fopen(part.path.c_str(), "rb"));
    if (!f) {
        const std::string why = errno == ENOENT ? "does not exist" : std::strerror(errno);
        throw failure(name, "cannot open data file " + part.path + ": " + why);
    }
    if (fseeko(f.get(), 0, SEEK_END) != 0) throw failure(name, "cannot seek in data file " + part.path);
    const off_t size = ftello(f.get());
    if (size < 0) throw failure(name, "cannot size data file " + part.path + " (not a regular file?)");
    fileSize = std::uint64_t(size);
    if (part.offset > fileSize)
        throw failure(name, "truncated: data file " + part.path + " has " + std::to_string(fileSize) +
                                " bytes, data should start at byte " + std::to_string(part.offset));
    return f;
}

void readPart(const PayloadPart& part, std::uint8_t* dst, std::uint64_t bytes, const std::string& name, Progress& progress)
{
    std::uint64_t fileSize = 0;
    const File f = openPart(part, name, fileSize);
    if (fseeko(f.get(), off_t(part.offset), SEEK_SET) != 0) throw failure(name, "cannot seek in data file " + part.path);
    skipLines(f.get(), part.lineSkip, name, part.path);
    if (part.compression == Compression::None)
        readUncompressed(f.get(), std::uint64_t(ftello(f.get())), fileSize, part, dst, bytes, name, progress);
    else
        readCompressed(f.get(), fileSize, part, dst, bytes, name, progress);
}

}  // namespace

void readPayload(const std::vector<PayloadPart>& parts, std::uint8_t* dst, std::uint64_t bytes, const std::string& name,
                 const osgDB::Options* options)
{
    if (parts.empty()) throw failure(name, "no data file");
    if (bytes % parts.size() != 0)
        throw failure(name, std::to_string(parts.size()) + " data files cannot hold " + std::to_string(bytes) +
                                " bytes in equal shares");
    Progress progress{options, name, double(bytes)};
    if (!reportLoadProgress(options, 0.0, double(bytes))) throw failure(name, "cancelled");
    const std::uint64_t share = bytes / parts.size();
    for (std::size_t i = 0; i < parts.size(); ++i) readPart(parts[i], dst + i * share, share, name, progress);
}

std::uint64_t uncompressedPayloadStart(const PayloadPart& part, std::uint64_t bytes, const std::string& name)
{
    if (part.compression != Compression::None) throw failure(name, "data file " + part.path + " is compressed");
    std::uint64_t fileSize = 0;
    const File f = openPart(part, name, fileSize);
    if (fseeko(f.get(), off_t(part.offset), SEEK_SET) != 0) throw failure(name, "cannot seek in data file " + part.path);
    skipLines(f.get(), part.lineSkip, name, part.path);
    return uncompressedBegin(std::uint64_t(ftello(f.get())), fileSize, part, bytes, name);
}

void checkPayloadFits(const std::vector<PayloadPart>& parts, std::uint64_t bytes, const std::string& name)
{
    if (parts.empty()) throw failure(name, "no data file");
    const std::uint64_t share = bytes / parts.size();
    for (const PayloadPart& part : parts) {
        std::uint64_t fileSize = 0;
        openPart(part, name, fileSize);
        // Skipped lines and bytes only lower this; byte skip -1 takes the file's last bytes.
        std::uint64_t available = part.byteSkip == -1 ? fileSize : fileSize - part.offset;
        if (part.compression == Compression::Zlib) {
            if (part.compressedSize) available = std::min(available, part.compressedSize);
            constexpr std::uint64_t maxRatio = 1040;  // deflate expands at most 1032:1
            if (available <= (std::uint64_t(-1) - 4096) / maxRatio && available * maxRatio + 4096 < share)
                throw failure(name, "truncated: " + std::to_string(available) + " bytes of compressed data in " + part.path +
                                        " cannot decode to the " + std::to_string(share) + " bytes the header needs");
        } else if (available < share) {
            throw failure(name, "truncated: data file " + part.path + " holds " + std::to_string(available) +
                                    " bytes of voxel data, the header needs " + std::to_string(share));
        }
    }
}

void swapBytes(std::uint8_t* data, std::size_t count, std::size_t width)
{
    if (width < 2) return;
    for (std::size_t i = 0; i < count; ++i) std::reverse(data + i * width, data + (i + 1) * width);
}

}  // namespace volren::rawvolume
