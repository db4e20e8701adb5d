#pragma once
#include <volume_model/Volume.h>

#include <string>

namespace volren::nrrd {

/// Writes `volume` as an attached-header NRRD (`dimension: 3`, or 4 with a leading `vector`
/// channel axis), native byte order, `spacings`, and the rescale as the key/value
/// `volren_rescale:=slope intercept`. `gzip` picks gzip encoding (else raw). Volumes with
/// several time points are refused. Throws std::runtime_error("path: reason").
void writeNrrd(const Volume& volume, const std::string& path, bool gzip);

}  // namespace volren::nrrd
