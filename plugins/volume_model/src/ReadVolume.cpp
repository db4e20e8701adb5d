#include <volume_model/DataSearchPath.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/Registry>

#include <cstdlib>
#include <dlfcn.h>
#include <mutex>
#include <stdexcept>

namespace volren {

namespace {

/// Folder holding this shared library (lib/ of the build or install tree).
std::string libraryDirectory()
{
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&libraryDirectory), &info) && info.dli_fname)
        return osgDB::getFilePath(osgDB::getRealPath(info.dli_fname));
    return {};
}

const char* const volumeExtensions[] = {"nii", "nrrd", "nhdr", "mhd", "mha", "raw", "dat", "tif", "tiff",
                                       "imgstack", "dcm", "dic", "dicom", "pvm", "zarr"};

/// The reader for a directory: an OME-Zarr image or zarr array (zarr metadata at its top),
/// numbered TIFF slices, other 2D images, else a DICOM series.
std::string directoryReader(const std::string& dir)
{
    bool images = false, files = false;
    for (const std::string& name : osgDB::getDirectoryContents(dir))
        if (name == ".zattrs" || name == ".zgroup" || name == ".zarray") return "zarr";
    for (const std::string& name : osgDB::getDirectoryContents(dir)) {
        if (name == "." || name == "..") continue;
        files = true;
        const std::string ext = osgDB::getLowerCaseFileExtension(name);
        if (ext == "tif" || ext == "tiff") return "tiff";
        if (ext == "png" || ext == "jpg" || ext == "jpeg" || ext == "bmp" || ext == "exr" || ext == "pgm") images = true;
    }
    if (!files) throw std::runtime_error(dir + ": empty directory (expected TIFF, 2D image or DICOM slices)");
    return images ? "imgstack" : "dicom";
}

}  // namespace

void registerPluginPath()
{
    static std::once_flag once;
    std::call_once(once, [] {
        const std::string dir = libraryDirectory();
        if (dir.empty()) return;
        auto& paths = osgDB::Registry::instance()->getLibraryFilePathList();
        if (std::find(paths.begin(), paths.end(), dir) == paths.end()) paths.push_front(dir);
    });
    registerDataPath();
}

std::string shareDirectory()
{
    if (const char* env = std::getenv("VOLREN_SHARE_DIR"); env && *env) return env;
    return osgDB::getRealPath(osgDB::concatPaths(libraryDirectory(), VOLREN_LIB_TO_SHARE));
}

std::string volumeFileExtension(const std::string& path)
{
    std::string ext = osgDB::getLowerCaseFileExtension(path);
    if (ext == "gz") ext = osgDB::getLowerCaseFileExtension(osgDB::getNameLessExtension(path));
    return ext;
}

bool isVolumeFile(const std::string& path)
{
    if (osgDB::fileType(path) == osgDB::DIRECTORY) return true;  // slices: TIFF, images or DICOM
    const std::string ext = volumeFileExtension(path);
    for (const char* known : volumeExtensions)
        if (ext == known) return true;
    return false;
}

osg::ref_ptr<Volume> readVolumeFile(const std::string& path, const osgDB::Options* options)
{
    registerPluginPath();
    // Numbered TIFF slices may be named by a pattern ("slices/s*.tif"): the reader expands it.
    const bool pattern = path.find_first_of("*?") != std::string::npos;
    if (!pattern && !osgDB::fileExists(path)) throw std::runtime_error(path + ": no such file");
    // A directory holds slices (TIFF, other 2D images, or a DICOM series) or is a zarr image.
    const bool isDirectory = !pattern && osgDB::fileType(path) == osgDB::DIRECTORY;
    const std::string named = volumeFileExtension(path);
    if (isDirectory && named != "dicom" && named != "zarr" && !osgDB::getLowerCaseFileExtension(path).empty())
        throw std::runtime_error(path + ": is a directory, not a volume file");
    const std::string ext = isDirectory && named != "zarr" ? directoryReader(path) : named;
    osgDB::ReaderWriter* rw = osgDB::Registry::instance()->getReaderWriterForExtension(ext);
    if (!rw) throw std::runtime_error(path + ": no volume reader for extension '" + ext + "'");
    if (std::string(rw->className()).rfind("volren", 0) != 0)  // e.g. OSG's own 2D osgdb_tiff, loaded first
        throw std::runtime_error(path + ": OSG's '" + rw->className() + "' plugin was loaded for '." + ext +
                                 "' before volren's; put volren's plugin folder first on OSG_LIBRARY_PATH");
    osgDB::ReaderWriter::ReadResult result = rw->readObject(path, options);
    if (!result.success()) {
        std::string why = result.message();
        if (why.empty()) why = "reader for '" + ext + "' failed (status " + std::to_string(int(result.status())) + ")";
        throw std::runtime_error(why.find(path) == std::string::npos ? path + ": " + why : why);
    }
    osg::ref_ptr<Volume> volume = dynamic_cast<Volume*>(result.getObject());
    if (!volume) throw std::runtime_error(path + ": reader did not return a volume");
    return volume;
}

}  // namespace volren
