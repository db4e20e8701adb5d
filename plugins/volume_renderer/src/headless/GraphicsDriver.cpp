#include <volume_renderer/GraphicsDriver.h>

#include <atomic>
#include <mutex>

namespace volren {

namespace {

std::mutex driverMutex;
std::string driverName;
std::atomic<bool> coarseBytes{false};  ///< decided when recorded: asked every cull

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

}  // namespace volren
