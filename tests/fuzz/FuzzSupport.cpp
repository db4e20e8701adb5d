#include "FuzzSupport.h"

#include <volume_model/ReadVolume.h>

#include <osg/Notify>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace volren::fuzz {

namespace {

/// Swallows OSG's messages: readers warn about every odd header, which would flood the log.
class Silent : public osg::NotifyHandler
{
public:
    void notify(osg::NotifySeverity, const char*) override {}
};

std::string makeScratchDir()
{
    silenceLogs();
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/volren-fuzz-XXXXXX";
    if (!mkdtemp(&pattern[0])) {
        std::perror("volren fuzz: mkdtemp");
        std::abort();
    }
    static std::string removeAtExit;
    removeAtExit = pattern;
    std::atexit([] {
        std::error_code ec;
        std::filesystem::remove_all(removeAtExit, ec);
    });
    return pattern;
}

}  // namespace

void silenceLogs()
{
    static const bool once = [] {
        osg::setNotifyHandler(new Silent);
        return true;
    }();
    (void)once;
}

const std::string& scratchDir()
{
    static const std::string dir = makeScratchDir();
    return dir;
}

std::string addScratchFile(const std::string& name, const std::uint8_t* data, std::size_t size)
{
    const std::string path = scratchDir() + "/" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out) {
        std::fprintf(stderr, "volren fuzz: cannot write %s\n", path.c_str());
        std::abort();
    }
    return path;
}

std::string writeScratchFile(const std::string& name, const std::uint8_t* data, std::size_t size)
{
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(scratchDir(), ec))
        std::filesystem::remove_all(entry.path(), ec);
    return addScratchFile(name, data, size);
}

std::pair<std::string, std::string> splitAtSeparator(const std::uint8_t* data, std::size_t size)
{
    const std::string all(reinterpret_cast<const char*>(data), size);
    const std::size_t at = all.find(dataSeparator);
    if (at == std::string::npos) return {all, std::string()};
    return {all.substr(0, at), all.substr(at + std::strlen(dataSeparator))};
}

void readVolumeIgnoringErrors(const std::string& path)
{
    try {
        volren::readVolumeFile(path);
    } catch (const std::exception& e) {
        // A clear error is the expected answer to a bad file (VOLREN_FUZZ_VERBOSE=1 prints it,
        // e.g. to check that the seeds read: fuzz_nrrd -runs=0 corpus/nrrd).
        static const bool verbose = std::getenv("VOLREN_FUZZ_VERBOSE") != nullptr;
        if (verbose) std::fprintf(stderr, "volren fuzz: %s\n", e.what());
        return;
    }
    static const bool verbose = std::getenv("VOLREN_FUZZ_VERBOSE") != nullptr;
    if (verbose) std::fprintf(stderr, "volren fuzz: read %s\n", path.c_str());
}

}  // namespace volren::fuzz
