// What a step of a time series costs on screen: a synthetic 2-channel series (a bright ball in
// each channel that moves from time point to time point) rendered headlessly; frames right
// after a step (each shown channel's block of the new time point copied out and uploaded) against
// frames without one, alternating, in one run.
// Usage: time_step_latency [WIDTHxHEIGHT] [ROUNDS] [EDGE]
#include "Median.h"

#include <volume_model/ChannelDisplay.h>
#include <volume_model/TimeSeries.h>
#include <volume_renderer/OffscreenRenderer.h>
#include <volume_renderer/VolumeScene.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <vector>

using volren::bench::median;

int main(int argc, char** argv)
{
    int width = 512, height = 512, rounds = 9, edge = 128;
    if (argc > 1 && std::sscanf(argv[1], "%dx%d", &width, &height) != 2) return std::cerr << "bad size\n", 2;
    if (argc > 2) rounds = std::max(1, std::atoi(argv[2]));
    if (argc > 3) edge = std::clamp(std::atoi(argv[3]), 8, 512);
    constexpr int channels = 2, timePoints = 6;
    osg::ref_ptr<volren::Volume> series = new volren::Volume;
    series->allocate(volren::VoxelType::UInt16, {edge, edge, edge}, channels, timePoints);
    for (int t = 0; t < timePoints; ++t)
        for (int c = 0; c < channels; ++c) {
            auto* voxels = reinterpret_cast<std::uint16_t*>(series->block(c, t));
            const double cx = edge * (0.3 + 0.08 * t), cy = edge * (0.4 + 0.2 * c), cz = edge * 0.5, r = edge * 0.2;
            for (int z = 0; z < edge; ++z)
                for (int y = 0; y < edge; ++y)
                    for (int x = 0; x < edge; ++x) {
                        const double d = std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz));
                        voxels[x + std::size_t(edge) * (y + std::size_t(edge) * z)] =
                            std::uint16_t(d < r ? 4000.0 * (1.0 - d / r) + 200.0 : 200.0);
                    }
        }
    series->dirty();
    osg::ref_ptr<volren::VolumeNode> node = new volren::VolumeNode;
    node->setVolume(series.get());
    node->setTransferFunction(volren::colourWindowTransferFunction({1, 1, 1}, 300, 4200, 0.2).get());
    node->channels = volren::defaultChannelDisplays(*series);
    osg::ref_ptr<volren::VolumeScene> scene = new volren::VolumeScene;
    scene->addChild(node.get());
    volren::OffscreenRenderer renderer(width, height);
    renderer.setScene(scene.get());
    const double size = double(edge);
    renderer.camera()->setViewMatrix(osg::Matrixd::lookAt(osg::Vec3d(0.6, -1.2, 0.8) * (2.2 * size), osg::Vec3d(), osg::Vec3d(0, 0, 1)));
    renderer.camera()->setProjectionMatrixAsPerspective(30.0, double(width) / height, 0.1 * size, 10.0 * size);
    volren::TimeSeries time(*scene);
    for (int i = 0; i < 2; ++i) renderer.renderFrame();  // warm-up: programs, textures

    std::vector<double> stepped, plain;
    const std::size_t copiesBefore = node->blockCopies();
    for (int r = 0; r < rounds; ++r) {
        const auto start = std::chrono::steady_clock::now();
        time.show((r + 1) % timePoints);
        renderer.renderFrame();
        stepped.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        const auto again = std::chrono::steady_clock::now();
        renderer.renderFrame();
        plain.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - again).count());
    }
    const double copies = double(node->blockCopies() - copiesBefore) / rounds;
    std::cout << channels << "-channel series of " << timePoints << " time points, " << edge << "^3 16-bit voxels per block, "
              << width << "x" << height << ", " << rounds << " rounds (" << renderer.contextDescription() << ")\n"
              << "frame after a time step: " << median(stepped) << " ms median (" << copies
              << " blocks copied and uploaded per step)\n"
              << "frame without a step:    " << median(plain) << " ms median\n"
              << "ratio: " << median(stepped) / median(plain) << "\n";
    return 0;
}
