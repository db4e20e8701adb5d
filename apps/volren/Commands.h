#pragma once
#include <volume_model/Volume.h>

#include <string>
#include <vector>

namespace volren::app {

/// `volren render INPUT -o OUT [...]` (and `volren` alone); returns the exit code.
int renderCommand(const std::vector<std::string>& args, bool defaultRun);
/// `volren reference INPUT -o OUT.exr [...]`: the CPU reference image of the same view as
/// `volren render` (emission-absorption only); returns the exit code.
int referenceCommand(const std::vector<std::string>& args);
/// `volren compare A B [--threshold T] [--diff OUT]`: error measures of image A against B.
int compareCommand(const std::vector<std::string>& args);
/// `volren info VOLUMEFILE`; returns the exit code.
int infoCommand(const std::vector<std::string>& args);
/// `volren convert IN OUT [--encoding raw|gzip] [-O KEY=VALUE ...]`: reads any volume file,
/// writes it through osgDB by OUT's extension (NRRD, OME-Zarr, a scene), passing -O words to the
/// writer, with a progress bar for writers that report it; returns the exit code.
int convertCommand(const std::vector<std::string>& args);
/// Reads a volume file with the reader options `readerOptions` (-O: "lazy ramBudgetMB=4096"),
/// drawing a one-line progress bar on stderr once the load takes over 0.5 s.
osg::ref_ptr<Volume> readVolumeWithProgress(const std::string& path, const std::string& readerOptions = {});
/// `volren view [INPUT]`: an interactive window; returns the exit code.
int viewCommand(const std::vector<std::string>& args);
/// `volren shader [INPUT] [--set ...]`: prints each volume's composed ray caster and key.
int shaderCommand(const std::vector<std::string>& args);
/// `volren bench [INPUT ...] [...]`: the speed-against-accuracy matrix (apps/volren/BenchCommand.cpp).
int benchCommand(const std::vector<std::string>& args);
/// `volren permutations [--list] [--compile] [--render] ...`: the composition sweep.
int permutationsCommand(const std::vector<std::string>& args);

}  // namespace volren::app
