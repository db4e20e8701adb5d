#include "DicomSeriesScan.h"
#include "DicomStructure.h"
#include "GdcmProbe.h"

#include <volume_model/ParseNumber.h>

#include <osg/Notify>

#include <gdcmImageReader.h>
#include <gdcmScanner.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <stdexcept>

namespace volren::dicom {

namespace {

const gdcm::Tag seriesUidTag(0x0020, 0x000e), positionTag(0x0020, 0x0032), orientationTag(0x0020, 0x0037),
    instanceTag(0x0020, 0x0013), rowsTag(0x0028, 0x0010), columnsTag(0x0028, 0x0011), framesTag(0x0028, 0x0008);

std::string trimmed(const char* text)
{
    std::string s = text ? text : "";
    const auto notSpace = [](char c) { return c != ' ' && c != '\0'; };
    s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
    s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
    return s;
}

/// Parses a backslash-separated list of exactly `count` numbers.
bool parseNumbers(const char* text, std::size_t count, double* out)
{
    const std::string s = trimmed(text);
    std::size_t start = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t end = s.find('\\', start);
        if ((end == std::string::npos) != (i + 1 == count)) return false;
        if (!parseFiniteNumber(trimmed(s.substr(start, end - start).c_str()), out[i])) return false;
        start = end + 1;
    }
    return true;
}

int parseInt(const char* text, int fallback)
{
    double v = 0.0;
    return parseFiniteNumber(trimmed(text), v) && v >= -2147483647.0 && v <= 2147483647.0 ? int(v) : fallback;
}

DicomSlice sliceOf(const gdcm::Scanner& scanner, const std::string& file)
{
    DicomSlice s;
    s.file = file;
    s.seriesUid = trimmed(scanner.GetValue(file.c_str(), seriesUidTag));
    s.rows = parseInt(scanner.GetValue(file.c_str(), rowsTag), 0);
    s.columns = parseInt(scanner.GetValue(file.c_str(), columnsTag), 0);
    s.frames = parseInt(scanner.GetValue(file.c_str(), framesTag), 1);
    s.instance = parseInt(scanner.GetValue(file.c_str(), instanceTag), 0);
    double v[6];
    if (parseNumbers(scanner.GetValue(file.c_str(), positionTag), 3, v)) {
        s.hasPosition = true;
        s.position.set(v[0], v[1], v[2]);
    }
    if (parseNumbers(scanner.GetValue(file.c_str(), orientationTag), 6, v)) {
        osg::Vec3d row(v[0], v[1], v[2]), column(v[3], v[4], v[5]);
        if (row.normalize() > 0.5 && column.normalize() > 0.5 && std::abs(row * column) < 1e-3) {
            s.hasOrientation = true;
            s.rowDirection = row;
            s.columnDirection = column;
        }
    }
    return s;
}

gdcm::Scanner makeScanner()
{
    gdcm::Scanner scanner;
    for (const gdcm::Tag& t : {seriesUidTag, positionTag, orientationTag, instanceTag, rowsTag, columnsTag, framesTag})
        scanner.AddTag(t);
    return scanner;
}

/// What the child-process probe runs per file: the same scan the real run makes, and GDCM's
/// full read and decode of the file (the image reader and its codecs can abort too).
void scanOne(const std::string& file)
{
    try {  // each step on its own: an exception in the scan must not skip the image read
        gdcm::Scanner scanner = makeScanner();
        scanner.Scan({file});
    } catch (...) {
    }
    gdcm::ImageReader reader;
    reader.SetFileName(file.c_str());
    if (!reader.Read()) return;
    // Decoding too: GDCM's codecs assert on inconsistent pixel descriptions.
    const gdcm::Image& image = reader.GetImage();
    std::vector<char> pixels(image.GetBufferLength());
    image.GetBuffer(pixels.data());
}

std::vector<std::string> filesIn(const std::string& dir)
{
    std::vector<std::string> files;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code typeError;
        if (it->is_regular_file(typeError)) files.push_back(it->path().string());
    }
    if (ec) throw std::runtime_error(dir + ": cannot list the directory: " + ec.message());
    std::sort(files.begin(), files.end());  // deterministic scan only; slices are ordered by position later
    return files;
}

}  // namespace

std::vector<DicomSlice> findSeries(const std::string& path, const std::string& seriesUid)
{
    std::error_code ec;
    const bool isDirectory = std::filesystem::is_directory(path, ec);
    std::string wanted = seriesUid;
    std::string dir = path;
    if (!isDirectory) {
        const Structure check = structureProblem(path);
        if (!check.problem.empty())
            throw std::runtime_error(path + (check.part10 ? ": malformed DICOM file: " : ": not a DICOM file: ") +
                                     check.problem);
        // GDCM 3.0 grows to gigabytes looking for missing pixel data in some malformed files.
        if (!check.pixelData) throw std::runtime_error(path + ": DICOM file without pixel data (7FE0,0010): not an image");
        if (const std::string aborted = probeInChild({path}, scanOne); !aborted.empty()) throw std::runtime_error(aborted);
        gdcm::Scanner single = makeScanner();
        if (!single.Scan({path}) || !single.IsKey(path.c_str())) throw std::runtime_error(path + ": not a DICOM file");
        const DicomSlice own = sliceOf(single, path);
        if (wanted.empty()) wanted = own.seriesUid;
        dir = std::filesystem::path(path).parent_path().string();
        if (dir.empty()) dir = ".";
    }

    // GDCM would abort the process on some malformed files: check them before it sees them. A
    // broken Part 10 file fails the whole read (skipping a slice would leave a gap in the volume);
    // other files that do not walk as DICOM data sets are not DICOM and are skipped.
    std::vector<std::string> files;
    for (const std::string& f : filesIn(dir)) {
        const Structure check = structureProblem(f);
        if (check.problem.empty() && check.pixelData) files.push_back(f);  // others are not images
        else if (check.part10 && !check.problem.empty()) throw std::runtime_error(f + ": malformed DICOM file: " + check.problem);
    }
    if (const std::string aborted = probeInChild(files, scanOne); !aborted.empty()) throw std::runtime_error(aborted);
    gdcm::Scanner scanner = makeScanner();
    if (!files.empty() && !scanner.Scan(files)) throw std::runtime_error(path + ": scanning the DICOM files failed");
    std::map<std::string, std::vector<DicomSlice>> series;
    for (const std::string& f : files)
        if (scanner.IsKey(f.c_str())) {
            DicomSlice s = sliceOf(scanner, f);
            series[s.seriesUid].push_back(std::move(s));
        }
    if (series.empty()) throw std::runtime_error(path + ": no DICOM files in " + dir);

    if (!wanted.empty()) {
        auto it = series.find(wanted);
        if (it == series.end()) {
            std::string known;
            for (const auto& [uid, slices] : series) known += (known.empty() ? "" : ", ") + uid;
            throw std::runtime_error(path + ": no DICOM series " + wanted + " (found: " + known + ")");
        }
        return it->second;
    }
    auto largest = series.begin();
    for (auto it = series.begin(); it != series.end(); ++it)
        if (it->second.size() > largest->second.size()) largest = it;
    if (series.size() > 1) {
        OSG_NOTICE << path << ": " << series.size() << " DICOM series; reading the largest, " << largest->first << " ("
                   << largest->second.size() << " slices); choose another with the option DicomSeries=<UID>:";
        for (const auto& [uid, slices] : series) OSG_NOTICE << " " << uid << " (" << slices.size() << ")";
        OSG_NOTICE << std::endl;
    }
    return largest->second;
}

}  // namespace volren::dicom
