#pragma once
#include <string>

namespace volren {

/// Records the GL_RENDERER of the context this process renders with (HeadlessContext and
/// `volren view` do, once their context is current; one driver per process is assumed).
void recordGraphicsDriver(const std::string& renderer);

/// The recorded GL_RENDERER, or "" when nothing recorded one (e.g. a stock OSG viewer).
std::string graphicsDriver();

/// Whether the recorded driver's linear filtering of 8-bit textures returns 8-bit results
/// (Mesa's llvmpipe and softpipe: measured, a ramp between two R8 texels comes back in steps of
/// 1/255), so that 8-bit volumes filter as finely as the reference only as 16-bit textures.
bool filtersBytesCoarsely();

}  // namespace volren
