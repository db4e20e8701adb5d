// libFuzzer target: DICOM through the osgDB reader (GDCM): the input is written as the only
// slice, fuzz.dcm, of the scratch folder, so the reader scans and reads a one-slice series.
#include "FuzzSupport.h"

#include <gdcmTrace.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const bool silenced = [] {
        gdcm::Trace::SetWarning(false);
        gdcm::Trace::SetError(false);
        gdcm::Trace::SetDebug(false);
        return true;
    }();
    (void)silenced;
    volren::fuzz::readVolumeIgnoringErrors(volren::fuzz::writeScratchFile("fuzz.dcm", data, size));
    return 0;
}
