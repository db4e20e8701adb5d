#pragma once
#include <set>
#include <string>

namespace volren {

/// The slots a build program (an implementation's compute shader that builds auxiliary data)
/// composes to sample and classify the volume, as the ray caster does: ProgramAssembly composes
/// them, and a built volume is rebuilt when any of their uniforms or textures change.
inline const std::set<std::string>& buildSamplingSlots()
{
    static const std::set<std::string> slots = {"VolumeStorage", "Reconstruction", "Classification", "ClipPosition",
                                                "Weighting"};
    return slots;
}

}  // namespace volren
