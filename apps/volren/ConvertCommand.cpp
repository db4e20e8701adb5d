#include "CommandLine.h"
#include "Commands.h"
#include "ProgressBar.h"

#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>

#include <osgDB/FileNameUtils>
#include <osgDB/Registry>

#include <iostream>
#include <stdexcept>

namespace volren::app {

int convertCommand(const std::vector<std::string>& args)
{
    std::vector<std::string> files;
    std::string encoding, writerOptions;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--encoding") {
            if (i + 1 >= args.size()) throw UsageError("--encoding needs raw or gzip");
            encoding = args[++i];
            if (encoding != "raw" && encoding != "gzip") throw UsageError("--encoding: '" + encoding + "' must be raw or gzip");
        } else if (args[i] == "-O" || args[i] == "--option") {
            // The writer plugin's own options, as osgconv's -O (e.g. chunk=32 for OME-Zarr).
            if (i + 1 >= args.size() || args[i + 1].find('=') == std::string::npos)
                throw UsageError(args[i] + " needs KEY=VALUE (e.g. -O chunk=32)");
            writerOptions += " " + args[++i];
        } else if (!args[i].empty() && args[i][0] == '-') {
            throw UsageError("convert: unknown option '" + args[i] + "'");
        } else {
            files.push_back(args[i]);
        }
    }
    if (files.size() != 2) throw UsageError("convert takes an input and an output file");
    const std::string& out = files[1];
    if (osgDB::getFileExtension(out).empty()) throw UsageError("convert: output '" + out + "' needs an extension (e.g. .nrrd)");

    osg::ref_ptr<Volume> volume = readVolumeWithProgress(files[0]);
    const osg::ref_ptr<osgDB::Options> written = new osgDB::Options((encoding.empty() ? "" : "encoding=" + encoding) + writerOptions);
    // An OSG scene file gets the volume's default scene (the volume referenced by its file).
    const std::string ext = osgDB::getLowerCaseFileExtension(out);
    const bool scene = ext == "osgt" || ext == "osgb" || ext == "osgx";
    const osgDB::ReaderWriter::WriteResult result = [&] {
        // Writers that report progress (OME-Zarr, per chunk) draw a bar once the write takes 0.5 s.
        const ProgressBar bar("writing", osgDB::getSimpleFileName(out));
        osg::ref_ptr<osgDB::Options> options = withLoadProgress(written.get(), &bar.callback());
        // osgDB::write*File's own path, keeping the writer's message for the error.
        return scene ? osgDB::Registry::instance()->writeNode(*makeDefaultScene(volume.get()), out, options.get())
                     : osgDB::Registry::instance()->writeObject(*volume, out, options.get());
    }();
    if (!result.success()) {
        std::string why = result.message();
        if (why.empty()) why = "no volume writer for extension '" + osgDB::getLowerCaseFileExtension(out) + "'";
        throw std::runtime_error(why.find(out) == std::string::npos ? out + ": " + why : why);
    }
    const osg::Vec3i& d = volume->dims();
    std::cout << files[0] << " -> " << out << (scene ? " (default scene; " : " (") << d.x() << " x " << d.y() << " x " << d.z() << " "
              << voxelTypeName(volume->type()) << ", " << volume->channels() << " channel"
              << (volume->channels() == 1 ? "" : "s") << ")\n";
    return 0;
}

}  // namespace volren::app
