#include <volume_renderer/GraphicsDriver.h>

#include <mutex>

namespace volren {

namespace {

std::mutex driverMutex;
std::string driverName;

}  // namespace

void recordGraphicsDriver(const std::string& renderer)
{
    std::lock_guard<std::mutex> lock(driverMutex);
    driverName = renderer;
}

std::string graphicsDriver()
{
    std::lock_guard<std::mutex> lock(driverMutex);
    return driverName;
}

bool filtersBytesCoarsely()
{
    const std::string name = graphicsDriver();
    return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
}

}  // namespace volren
