#include "TiffFile.h"

#include <osg/Notify>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace volren::tiff {

namespace {

std::string format(const char* module, const char* fmt, va_list ap)
{
    char text[1024];
    std::vsnprintf(text, sizeof(text), fmt, ap);
    return (module && *module) ? std::string(module) + ": " + text : std::string(text);
}

}  // namespace

TiffFile::TiffFile(const std::string& path) : _path(path)
{
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error(path + ": no such file");
    _size = std::filesystem::file_size(path, ec);
    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, &TiffFile::onError, this);
    TIFFOpenOptionsSetWarningHandlerExtR(options, &TiffFile::onWarning, this);
    TIFFOpenOptionsSetMaxSingleMemAlloc(options, tmsize_t(1) << 31);
    _tif = TIFFOpenExt(path.c_str(), "r", options);
    TIFFOpenOptionsFree(options);
    if (!_tif) fail("cannot open as TIFF");
}

TiffFile::~TiffFile()
{
    if (_tif) TIFFClose(_tif);
}

std::string TiffFile::takeError()
{
    std::string error;
    error.swap(_error);
    return error;
}

void TiffFile::fail(const std::string& what)
{
    const std::string error = takeError();
    throw std::runtime_error(_path + ": " + what + (error.empty() ? "" : ": " + error));
}

int TiffFile::onError(TIFF*, void* self, const char* module, const char* fmt, va_list ap)
{
    auto* file = static_cast<TiffFile*>(self);
    if (module && file->_path == module) module = nullptr;  // messages already name the file
    if (file->_error.empty()) file->_error = format(module, fmt, ap);  // the first error is the cause
    return 1;
}

int TiffFile::onWarning(TIFF*, void* self, const char* module, const char* fmt, va_list ap)
{
    // Private tags (ImageJ's 50838/50839, ...) are reported as unknown fields: not worth a warning.
    OSG_INFO << static_cast<TiffFile*>(self)->_path << ": libtiff: " << format(module, fmt, ap) << std::endl;
    return 1;
}

}  // namespace volren::tiff
