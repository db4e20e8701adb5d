#pragma once
#include <volume_model/Volume.h>
#include <volume_model/ZarrArrayMetadata.h>

#include <osgDB/Options>

#include <cstdint>
#include <string>

namespace volren::omezarr {

/// How the writer chunks and compresses the pyramid: the plugin's write options.
struct WriteSettings
{
    std::uint64_t chunk = 64;  ///< chunk edge along z, y, x (option chunk=N, 1 to 1024)
    ZarrCompressor compressor{"blosc", "lz4", 5, 1, 0};  ///< option compression=NAME (blosc lz4 + byte shuffle)
};

/// Parses the writer's words in `optionString`: chunk=N and compression=blosc-lz4 (default),
/// blosc-lz4hc, blosc-zstd, blosc-zlib, blosc-blosclz, zlib, gzip or none; other words are
/// left to other readers. Throws std::runtime_error naming a bad value.
WriteSettings parseWriteSettings(const std::string& optionString);

/// Writes `volume` as an OME-Zarr 0.4 image folder at `path`: level 0 the voxels as stored,
/// each next level halveByMean of the one before, until every axis fits in one chunk; axes
/// z y x, preceded by c and t when the volume has several channels or time points; scale and
/// translation per level (voxel centres of all levels line up), `/` chunk separator, fill 0.
/// The rescale goes into `.zattrs` as "volren": {"rescale": [slope, intercept]}. Progress per
/// chunk goes to the LoadProgress in `options` (a cancel fails the write). The folder is built
/// beside `path` under a temporary name and renamed into place at the end, so a failed write
/// leaves nothing at `path`; an existing zarr (or empty) folder there is replaced only on success, and
/// anything else there is refused. Throws std::runtime_error("path: reason").
void writeOmeZarr(const Volume& volume, const std::string& path, const WriteSettings& settings, const osgDB::Options* options);

}  // namespace volren::omezarr
