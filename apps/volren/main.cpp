// volren: render volumes in OpenSceneGraph scenes, headless or in a window.
#include "CommandLine.h"
#include "Commands.h"
#include "SceneSetup.h"

#include <volume_renderer/SceneSettings.h>

#include <iostream>
#include <string>
#include <vector>

namespace {

const char* const usage =
    "usage:\n"
    "  volren                          render the default scene to volren.png\n"
    "  volren render INPUT -o OUT.png [--size WxH] [--eye x,y,z --center x,y,z --up x,y,z]\n"
    "                [--fov DEG | --ortho HEIGHT] [--background r,g,b]\n"
    "                [--tf FILE.tf | --tf PRESETS.json[#NAME] [--tf-keep-range]]\n"
    "                [--set KEY=VALUE ...] [--frames N] [--samples N] [--stats FILE.json]\n"
    "                [-O OPTION ...]   reader options: -O lazy (keep the file's finer levels on disk,\n"
    "                read by brick), -O ramBudgetMB=N (files over N MiB open lazily; default: 1/4 of RAM)\n"
    "  volren reference INPUT -o OUT.exr [render's options] [--normals central|exact]   CPU reference image\n"
    "  volren compare A B [--threshold T] [--diff OUT]   RMSE, PSNR, max error, pixels over T\n"
    "  volren info VOLUMEFILE [-O OPTION ...]   dims, type, spacing, value range, histogram\n"
    "  volren convert IN OUT [--encoding raw|gzip] [-O KEY=VALUE ...]   read any volume file, write\n"
    "                                OUT.nrrd, OUT.ome.zarr (multiscale pyramid; -O chunk=N,\n"
    "                                -O compression=blosc-lz4|blosc-zstd|zlib|gzip|none) or\n"
    "                                OUT.osgt/.osgb/.osgx (the volume's default scene)\n"
    "  volren view [INPUT] [options]   interactive window (needs a display)\n"
    "  volren shader [INPUT] [--set KEY=VALUE ...]   print each volume's composed ray caster\n"
    "  volren bench [INPUT ...] [--size WxH[,WxH...]] [--frames N] [--out DIR] [--configs 'A;B'] [--vtk] [--tf FILE]\n"
    "                [--tolerance T] [--normals central|exact] [--check-front]   speed against accuracy: table, CSV,\n"
    "                JSON, plot; --check-front fails when a row beats the default on both axes\n"
    "  volren permutations [--list] [--compile | --render] [--pairwise] [--max-instances N]\n"
    "                [--max-lights N] [--shard I/N] [--first I] [--count N] [--stats FILE.json]\n"
    "                [--dump DIR]   (with --render: each composition's source and image into DIR)\n"
    "  volren render --help-settings   every --set KEY with its default, every implementation\n";

}  // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> args(argv + 1, argv + argc);
    const std::string command = args.empty() ? "" : args.front();
    if (!args.empty()) args.erase(args.begin());
    try {
        for (const std::string& a : args)
            if (a == "--help-settings") {
                std::cout << volren::settingsHelp(volren::CompositionPolicy());
                return 0;
            }
        if (command == "--help-settings") {
            std::cout << volren::settingsHelp(volren::CompositionPolicy());
            return 0;
        }
        if (command.empty()) return volren::app::renderCommand({}, true);
        if (command == "shader") return volren::app::shaderCommand(args);
        if (command == "permutations") return volren::app::permutationsCommand(args);
        if (command == "render") return volren::app::renderCommand(args, false);
        if (command == "reference") return volren::app::referenceCommand(args);
        if (command == "compare") return volren::app::compareCommand(args);
        if (command == "info") return volren::app::infoCommand(args);
        if (command == "convert") return volren::app::convertCommand(args);
        if (command == "view") return volren::app::viewCommand(args);
        if (command == "bench") return volren::app::benchCommand(args);
        if (command == "-h" || command == "--help" || command == "help") {
            std::cout << usage;
            return 0;
        }
        throw volren::app::UsageError("unknown command '" + command + "'");
    } catch (const volren::app::UsageError& e) {
        std::cerr << "volren: " << e.what() << "\n" << usage;
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "volren: error: " << e.what() << std::endl;
        return 1;
    }
}
