// libFuzzer target: TIFF stacks (multi-page, ImageJ hyperstack, OME-TIFF) through the osgDB
// reader: the input is written as fuzz.tif and read with libtiff by volren's stack reader.
#include "FuzzSupport.h"

#include <tiffio.h>

namespace {
void quiet(const char*, const char*, va_list) {}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const bool silenced = [] {
        TIFFSetWarningHandler(quiet);  // libtiff would print every complaint; the reader
        TIFFSetErrorHandler(quiet);    // turns failed libtiff calls into exceptions itself
        return true;
    }();
    (void)silenced;
    volren::fuzz::readVolumeIgnoringErrors(volren::fuzz::writeScratchFile("fuzz.tif", data, size));
    return 0;
}
