#include "CommandLine.h"
#include "Commands.h"
#include "ProgressBar.h"

#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/SceneInputs.h>

#include <osgDB/FileNameUtils>
#include <osgDB/Registry>

#include <iostream>
#include <stdexcept>

namespace volren::app {

namespace {

/// "48 x 62 x 42 uint8, 1 channel"
std::string describe(const Volume& volume)
{
    const osg::Vec3i& d = volume.dims();
    return std::to_string(d.x()) + " x " + std::to_string(d.y()) + " x " + std::to_string(d.z()) + " " +
           voxelTypeName(volume.type()) + ", " + std::to_string(volume.channels()) + " channel" +
           (volume.channels() == 1 ? "" : "s");
}

}  // namespace

int convertCommand(const std::vector<std::string>& args)
{
    std::vector<std::string> files;
    std::string encoding, writerOptions;
    std::vector<std::string> placements;  // --place N:SPEC, checked once the inputs are known
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
        } else if (args[i] == "--place") {
            if (i + 1 >= args.size()) throw UsageError("--place needs N:tx,ty,tz[:scale][:axis,angle]");
            placements.push_back(args[++i]);
        } else if (!args[i].empty() && args[i][0] == '-') {
            throw UsageError("convert: unknown option '" + args[i] + "'");
        } else {
            files.push_back(args[i]);
        }
    }
    if (files.size() < 2) throw UsageError("convert takes input files and an output file");
    const std::string out = files.back();
    files.pop_back();
    if (osgDB::getFileExtension(out).empty()) throw UsageError("convert: output '" + out + "' needs an extension (e.g. .nrrd)");
    // An OSG scene file gets the inputs' combined scene (volumes and models referred to by path).
    const std::string ext = osgDB::getLowerCaseFileExtension(out);
    const bool scene = ext == "osgt" || ext == "osgb" || ext == "osgx";
    if (!scene && (files.size() > 1 || !placements.empty()))
        throw UsageError("convert: several inputs or --place need a scene output (.osgt, .osgb, .osgx)");

    osg::ref_ptr<osg::Node> combined;
    osg::ref_ptr<Volume> volume;
    if (scene) {
        std::vector<SceneInput> inputs;
        for (const std::string& file : files) inputs.push_back({file, std::nullopt});
        for (const std::string& p : placements) {
            const auto [n, placement] = parsePlaceOption(p);
            checkPlacedInput(n, inputs.size());
            inputs[n].placement = placement;
        }
        combined = readSceneInputs(inputs, [](const std::string& path) { return readVolumeWithProgress(path); });
        makeModelPathsRelative(*combined, osgDB::getFilePath(osgDB::getRealPath(out)));
    } else {
        volume = readVolumeWithProgress(files[0]);
    }
    const osg::ref_ptr<osgDB::Options> written = new osgDB::Options((encoding.empty() ? "" : "encoding=" + encoding) + writerOptions);
    const osgDB::ReaderWriter::WriteResult result = [&] {
        // Writers that report progress (OME-Zarr, per chunk) draw a bar once the write takes 0.5 s.
        const ProgressBar bar("writing", osgDB::getSimpleFileName(out));
        osg::ref_ptr<osgDB::Options> options = withLoadProgress(written.get(), &bar.callback());
        // osgDB::write*File's own path, keeping the writer's message for the error.
        return scene ? osgDB::Registry::instance()->writeNode(*combined, out, options.get())
                     : osgDB::Registry::instance()->writeObject(*volume, out, options.get());
    }();
    if (!result.success()) {
        std::string why = result.message();
        if (why.empty()) why = "no volume writer for extension '" + osgDB::getLowerCaseFileExtension(out) + "'";
        throw std::runtime_error(why.find(out) == std::string::npos ? out + ": " + why : why);
    }
    std::string names;
    for (const std::string& file : files) names += (names.empty() ? "" : " + ") + file;
    if (scene) {
        const std::vector<VolumeNode*> nodes = findVolumeNodes(*combined);
        if (files.size() == 1 && nodes.size() == 1 && nodes[0]->getVolume())
            std::cout << names << " -> " << out << " (default scene; " << describe(*nodes[0]->getVolume()) << ")\n";
        else
            std::cout << names << " -> " << out << " (scene of " << files.size() << " inputs, " << nodes.size() << " volume"
                      << (nodes.size() == 1 ? "" : "s") << ")\n";
    } else {
        std::cout << names << " -> " << out << " (" << describe(*volume) << ")\n";
    }
    return 0;
}

}  // namespace volren::app
