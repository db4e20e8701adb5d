#pragma once
#include <volume_model/RenderSettings.h>

#include <osg/Vec3i>

#include <cstddef>
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

/// Records the context's GL_MAX_3D_TEXTURE_SIZE and its dedicated video memory in bytes (0 where
/// the driver does not report it: GL_NVX_gpu_memory_info, GL_ATI_meminfo).
void recordGraphicsLimits(int largest3DTexture, std::size_t dedicatedMemory);

/// The recorded largest 3D texture edge, or 2048 (what every OpenGL 4.5 driver allows).
int largest3DTexture();

/// Whether a 3D texture of `dims` texels is larger than largest3DTexture() along some axis (OSG
/// would shrink its image silently).
bool exceedsLargest3DTexture(const osg::Vec3i& dims);

/// GPU bytes one volume's voxels may take: memoryBudgetMB when set, else half the recorded
/// dedicated memory, else 2 GiB.
std::size_t volumeMemoryBudget(const RenderSettings& settings);

}  // namespace volren
