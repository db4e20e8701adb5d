#pragma once
#include "PayloadVolume.h"

#include <string>

namespace volren::rawvolume {

/// Layout of a headerless `.raw` file from "key=value" words: dims=X,Y,Z type=uint16
/// endian=little|big skip=BYTES spacing=X,Y,Z channels=N encoding=raw|gzip. Words come from
/// the sidecar `FILE.raw.txt` (if present; unknown keys there are errors, `#` starts a
/// comment), then from the option string (overrides; unknown keys ignored). Throws
/// std::runtime_error("path: reason").
PayloadLayout describeRawFile(const std::string& path, const std::string& optionString);

}  // namespace volren::rawvolume
