#pragma once

namespace volren::app {

/// Text of scenes/default.osgt, compiled into the program (its volume, ch2.nii.gz, is found in
/// share/volren/data).
const char* defaultSceneText();

}  // namespace volren::app
