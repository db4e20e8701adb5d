// Rendering pins no thread: OSG's single-threaded viewer pins the thread that sets it up to CPU 0
// unless told not to, and every thread started afterwards (the reference's workers, brick
// loaders) inherits the pin, so they all share one core. After a frame, the rendering thread and
// a thread it starts may run on every CPU the process could run on at start.
#include "RenderFixture.h"
#include "TestData.h"

#include <gtest/gtest.h>

#include <sched.h>

#include <thread>

namespace volren::test {
namespace {

/// The CPUs the calling thread may run on.
cpu_set_t allowedCpus()
{
    cpu_set_t set;
    CPU_ZERO(&set);
    sched_getaffinity(0, sizeof(set), &set);
    return set;
}

/// What the process may run on before anything renders (read as the test binary loads).
const cpu_set_t atStart = allowedCpus();

class ThreadAffinity : public RenderFixture
{
};

TEST_F(ThreadAffinity, AfterAFrameNoThreadIsPinned)
{
    osg::ref_ptr<VolumeNode> node = makeVolumeNode(constantVolume(VoxelType::UInt8, {4, 4, 4}, 7).get(),
                                                   constantTransferFunction(osg::Vec4(1, 1, 1, 0.5f)).get());
    renderOrthoFromPlusZ(node.get(), 8, 8, 10.0);
    const cpu_set_t rendering = allowedCpus();
    cpu_set_t started;
    std::thread([&started] { started = allowedCpus(); }).join();
    EXPECT_TRUE(CPU_EQUAL(&rendering, &atStart)) << CPU_COUNT(&rendering) << " of " << CPU_COUNT(&atStart) << " CPUs";
    EXPECT_TRUE(CPU_EQUAL(&started, &atStart)) << CPU_COUNT(&started) << " of " << CPU_COUNT(&atStart) << " CPUs";
}

}  // namespace
}  // namespace volren::test
