// libFuzzer target: PVM. The bytes go straight to readPvm, the parser the osgdb_pvm plugin
// hands the whole file to.
#include "FuzzSupport.h"
#include "PvmReader.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    volren::fuzz::silenceLogs();
    try {
        volren::pvm::readPvm(std::vector<std::uint8_t>(data, data + size), "fuzz.pvm");
    } catch (const std::exception&) {
    }
    return 0;
}
