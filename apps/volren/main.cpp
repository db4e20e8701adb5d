// volren: render volumes in OpenSceneGraph scenes, headless or in a window.
#include "CommandLine.h"
#include "Commands.h"
#include "SceneSetup.h"

#include <volume_renderer/SceneSettings.h>

#include <iostream>
#include <string>
#include <vector>

namespace {

/// Each command's usage, in the order `volren --help` lists them.
const std::vector<std::pair<std::string, std::string>>& commandUsages()
{
    static const std::vector<std::pair<std::string, std::string>> usages = {
        {"", "  volren                          render the default scene to volren.png\n"},
        {"render",
         "  volren render [INPUT ...] -o OUT.png [--size WxH] [--eye x,y,z --center x,y,z --up x,y,z]\n"
         "                [--fov DEG | --ortho fit|HEIGHT] [--background r,g,b] [--place N:PLACEMENT ...]\n"
         "                [--tf FILE.tf|FILE.vp|FILE.lut | --tf PRESETS.json[#NAME] [--tf-keep-range]]\n"
         "                [--set KEY=VALUE ...] [--frames N] [--samples N] [--stats FILE.json]\n"
         "                [--turntable N [--axis x|y|z|ax,ay,az]] [--time K|all] [--scale-bar] [--axes]\n"
         "                [-O OPTION ...]\n"
         "                INPUT: scene (.osgt/.osgb/.osgx), volume or model (.obj, .ply, .stl, .osg, ...) files,\n"
         "                combined in one scene (none: the default scene); PLACEMENT of input N (1 = first):\n"
         "                tx,ty,tz[:s|:sx,sy,sz][:x|y|z|ax,ay,az,DEGREES] (scaled, rotated, then moved)\n"
         "                --turntable N: N frames around the scene, OUT_0001.png ... (OUT.gif: one animated GIF)\n"
         "                --time K: time point K (from 0) of time-series volumes; all: a frame per time point\n"
         "                (with --turntable N, the time points spread over its N frames)\n"
         "                multi-channel volumes show every channel in one ray (--set channels=0,2: those;\n"
         "                --set traversal=additive|mip: the channels' images or maxima added)\n"
         "                --scale-bar: a scale bar in the volume's unit; --axes: the world axes (both on in view;\n"
         "                --no-scale-bar, --no-axes there)\n"
         "                -O: reader options: -O lazy (keep the file's finer levels on disk, read by brick),\n"
         "                -O ramBudgetMB=N (files over N MiB open lazily; default: 1/4 of RAM)\n"
         "  volren render --help-settings   every --set KEY with its default, every implementation\n"},
        {"reference", "  volren reference [INPUT ...] -o OUT.exr [render's options] [--normals central|exact]   CPU reference image\n"},
        {"compare", "  volren compare A B [--threshold T] [--diff OUT]   RMSE, PSNR, max error, pixels over T\n"},
        {"info", "  volren info VOLUMEFILE [-O OPTION ...]   dims, type, spacing, value range, histogram\n"},
        {"convert",
         "  volren convert IN OUT [--encoding raw|gzip] [-O KEY=VALUE ...]   read any volume file, write\n"
         "                                OUT.nrrd, OUT.ome.zarr (multiscale pyramid; -O chunk=N,\n"
         "                                -O compression=blosc-lz4|blosc-zstd|zlib|gzip|none) or\n"
         "                                OUT.osgt/.osgb/.osgx (the volume's default scene)\n"
         "  volren convert IN ... OUT.osgt [--place N:PLACEMENT ...]   several scene, volume and model\n"
         "                                files combined into one scene file (files referred to by path)\n"},
        {"view", "  volren view [INPUT ...] [render's options] [--screenshot OUT]   interactive window (needs a display)\n"},
        {"shader", "  volren shader [INPUT ...] [--set KEY=VALUE ...]   print each volume's composed ray caster\n"},
        {"bench",
         "  volren bench [DATASET ...] [--size WxH[,WxH...]] [--frames N] [--out DIR] [--configs 'A;B'] [--vtk] [--tf FILE]\n"
         "                [--tolerance T] [--normals central|exact] [--check-front] [--list-configs]   speed against\n"
         "                accuracy: table, CSV, JSON, plot; --check-front fails when a row beats the default (better on\n"
         "                one axis beyond the noise, not worse on the other); --list-configs prints the matrix (settings,\n"
         "                then each implementation's declared rows);\n"
         "                DATASET: an input, or inputs joined by '+' (ct.nii.gz+tool.obj) measured as one scene\n"},
        {"permutations",
         "  volren permutations [--list] [--compile | --render] [--pairwise] [--max-instances N]\n"
         "                [--max-lights N] [--shard I/N] [--first I] [--count N] [--stats FILE.json]\n"
         "                [--dump DIR]   (with --render: each composition's source and image into DIR)\n"
         "                [--where SLOT=NAME]...   (only compositions that choose these implementations; with\n"
         "                --pairwise, the pairwise cover of those compositions)\n"
         "                [--modelled]   (only compositions whose every implementation declares a reference\n"
         "                model, all compared with the CPU reference; with --pairwise, that subspace's cover)\n"
         "                [--extremes]   (with --render: each composition also on the sweep scene at parameter\n"
         "                extremes: 8/16-bit data, NaN voxels, opacity 0 and 1, steps of 1/1000 voxel, spacings\n"
         "                1e-9 and 1e12, 1x1x1 and 4096x4x4 volumes, the camera inside, 1x1 and 4096x4 views)\n"
         "                [--variant TEXT]   (with --extremes: only the variants whose name holds TEXT)\n"
         "                [--no-check] [--time-limit MS]   (--render checks each frame: composing, compile\n"
         "                and link, GL errors, finite pixels, the volume drawn, the frame's time; it exits 1\n"
         "                and prints 'FAILED <key>: <check>: <measured>' for each failed check)\n"},
        {"--help", "  volren --help | volren COMMAND --help | volren --version\n"},
    };
    return usages;
}

/// The usage of every command.
std::string usage()
{
    std::string text = "usage:\n";
    for (const auto& [command, lines] : commandUsages()) text += lines;
    return text;
}

/// The usage of `command`, or of every command when it is not one.
std::string usageOf(const std::string& command)
{
    for (const auto& [name, lines] : commandUsages())
        if (name == command && !command.empty() && command != "--help") return "usage:\n" + lines;
    return usage();
}

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
        if (command == "--version" || command == "-V") {
            std::cout << "volren " << VOLREN_VERSION << "\n";
            return 0;
        }
        for (const std::string& a : args)  // volren COMMAND --help: that command's usage
            if (a == "--help" || a == "-h") {
                std::cout << usageOf(command);
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
            std::cout << usage();
            return 0;
        }
        throw volren::app::UsageError("unknown command '" + command + "'");
    } catch (const volren::app::UsageError& e) {
        std::cerr << "volren: " << e.what() << "\n" << usageOf(command);
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "volren: error: " << e.what() << std::endl;
        return 1;
    }
}
