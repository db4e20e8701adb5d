#pragma once
// When a volume reader opens a file lazily (a preview level in memory, every level read on
// demand through a BrickSource) instead of reading it whole: the reader options `lazy` and
// `ramBudgetMB=N`, shared by the raw-style readers and OME-Zarr.
#include <volume_model/BrickSource.h>

#include <osgDB/Options>

#include <algorithm>
#include <cstdint>

namespace volren {

/// The lazy-opening settings of one read.
struct LazyOpening
{
    /// Largest preview level kept in memory (64 MiB), less when the RAM budget is small.
    static constexpr std::uint64_t maxPreviewBytes = std::uint64_t(64) << 20;

    bool requested = false;       ///< option `lazy`: open lazily whatever the size
    std::uint64_t ramBudget = 0;  ///< bytes: option ramBudgetMB=N (MiB, may be fractional), else a quarter of physical RAM

    /// Whether a payload of `bytes` opens lazily: requested, or bytes > ramBudget
    /// (so ramBudgetMB=0 opens every payload lazily).
    bool opensLazily(std::uint64_t bytes) const { return requested || bytes > ramBudget; }
    /// Bytes of the preview level: min(maxPreviewBytes, ramBudget / 8).
    std::uint64_t previewBudget() const;
    /// Bytes of decoded chunks a lazy OME-Zarr keeps: min(256 MiB, ramBudget / 4).
    std::uint64_t chunkCacheBudget() const { return std::min<std::uint64_t>(std::uint64_t(256) << 20, ramBudget / 4); }
};

/// The settings in `options`' option string (words `lazy`, `ramBudgetMB=N`); throws
/// std::runtime_error("option ramBudgetMB=...: ...") when N is not a non-negative number.
LazyOpening lazyOpeningOf(const osgDB::Options* options);

/// Physical RAM in bytes (sysconf), or 0 when unknown.
std::uint64_t physicalMemoryBytes();

/// Bytes of level `level` of `source` (voxels x voxel size).
std::uint64_t levelBytes(const BrickSource& source, int level);

/// The finest level of `source` whose voxels fit `budget` bytes, else its coarsest level.
int previewLevelFor(const BrickSource& source, std::uint64_t budget);

}  // namespace volren
