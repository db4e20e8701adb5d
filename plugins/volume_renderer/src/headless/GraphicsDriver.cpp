#include <volume_renderer/GraphicsDriver.h>

#include <algorithm>
#include <atomic>
#include <mutex>

namespace volren {

namespace {

std::mutex driverMutex;
std::string driverName;
std::atomic<bool> coarseBytes{false};  ///< decided when recorded: asked every cull
std::atomic<int> largest3D{0};
std::atomic<std::size_t> videoMemory{0};

}  // namespace

void recordGraphicsDriver(const std::string& renderer)
{
    std::lock_guard<std::mutex> lock(driverMutex);
    driverName = renderer;
    coarseBytes = renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

std::string graphicsDriver()
{
    std::lock_guard<std::mutex> lock(driverMutex);
    return driverName;
}

bool filtersBytesCoarsely()
{
    return coarseBytes;
}

void recordGraphicsLimits(int largest3DTexture, std::size_t dedicatedMemory)
{
    largest3D = largest3DTexture;
    videoMemory = dedicatedMemory;
}

int largest3DTexture()
{
    const int recorded = largest3D;
    return recorded > 0 ? recorded : 2048;
}

bool exceedsLargest3DTexture(const osg::Vec3i& dims)
{
    return std::max({dims.x(), dims.y(), dims.z()}) > largest3DTexture();
}

std::size_t volumeMemoryBudget(const RenderSettings& settings)
{
    if (settings.memoryBudgetMB > 0) return std::size_t(settings.memoryBudgetMB) << 20;
    const std::size_t memory = videoMemory;
    return memory > 0 ? memory / 2 : std::size_t(2048) << 20;
}

}  // namespace volren
