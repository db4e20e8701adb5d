#pragma once
#include <string>
#include <vector>

namespace volren {

/// A shader-function slot: its name and the implementation used when the scene asks for nothing.
struct SlotInfo
{
    std::string name;            ///< e.g. "Classification"
    std::string defaultFunction;  ///< e.g. "tf1d"
};

/// All slots, in the order their implementations are emitted. Signatures: shaders/slots.glsl.
const std::vector<SlotInfo>& slots();

}  // namespace volren
