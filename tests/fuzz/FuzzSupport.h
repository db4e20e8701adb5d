#pragma once
// Shared helpers of the volren libFuzzer targets: a per-process scratch folder that each input
// is written into (as the file the real reader opens), and quiet OSG logging.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

namespace volren::fuzz {

/// Separates the header text from the data file bytes in the inputs of the detached formats
/// (.nhdr, .mhd, .raw + .raw.txt, .dat): HEADER + separator + DATA.
constexpr char dataSeparator[] = "\n==data==\n";

/// Silences OSG's notify output (readers warn about every odd header; the log would flood).
void silenceLogs();

/// The scratch folder of this process ($TMPDIR or /tmp/volren-fuzz-XXXXXX), emptied before
/// every input and removed at exit. Also calls silenceLogs().
const std::string& scratchDir();

/// Empties the scratch folder, then writes `size` bytes to scratchDir()/name; returns the path.
std::string writeScratchFile(const std::string& name, const std::uint8_t* data, std::size_t size);
/// Writes one more file into the scratch folder (not emptied); returns the path.
std::string addScratchFile(const std::string& name, const std::uint8_t* data, std::size_t size);

/// (header, data) split at the first dataSeparator; data is empty when there is none.
std::pair<std::string, std::string> splitAtSeparator(const std::uint8_t* data, std::size_t size);

/// Reads `path` through osgDB exactly as volren::readVolumeFile does; an error result (an
/// exception) is a normal outcome, anything else (crash, sanitizer report, hang) a finding.
void readVolumeIgnoringErrors(const std::string& path);

}  // namespace volren::fuzz
