#pragma once
#include <tiffio.h>

#include <string>

namespace volren::tiff {

/// An open TIFF file (read only) that collects libtiff's error messages instead of printing them.
class TiffFile
{
public:
    /// Opens `path`; throws std::runtime_error("path: reason") when libtiff cannot.
    explicit TiffFile(const std::string& path);
    ~TiffFile();
    TiffFile(const TiffFile&) = delete;
    TiffFile& operator=(const TiffFile&) = delete;

    TIFF* handle() const { return _tif; }                 ///< the libtiff handle
    const std::string& path() const { return _path; }     ///< the file's path
    unsigned long long fileSize() const { return _size; }  ///< bytes in the file
    /// libtiff's last error message (empty when none), cleared by the call.
    std::string takeError();
    /// Throws std::runtime_error("path: what: libtiff's error").
    [[noreturn]] void fail(const std::string& what);

private:
    static int onError(TIFF*, void* self, const char* module, const char* fmt, va_list ap);
    static int onWarning(TIFF*, void* self, const char* module, const char* fmt, va_list ap);

    std::string _path;
    std::string _error;
    unsigned long long _size = 0;
    TIFF* _tif = nullptr;
};

}  // namespace volren::tiff
