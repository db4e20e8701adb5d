// How long a transfer-function edit takes to reach the screen: the default scene rendered
// headlessly; frames after an edit (a control point moved, as a drag in the editor does) against
// frames without one, alternating, in one run. The extra time is the TF table's rebuild and
// upload and the occupancy grid's rebuild (empty-space skipping); the frame itself is the rest.
// Also the macrocell value-range grid's build, once per volume, on the CPU.
// Usage: tf_edit_latency [WIDTHxHEIGHT] [ROUNDS] [--no-skipping]
#include "Median.h"

#include <volume_model/ReadVolume.h>
#include <volume_renderer/MacrocellGrid.h>
#include <volume_renderer/OffscreenRenderer.h>

#include <osg/NodeVisitor>
#include <osgDB/ReadFile>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

using volren::bench::median;

int main(int argc, char** argv)
{
    int width = 512, height = 512, rounds = 9;
    if (argc > 1 && std::sscanf(argv[1], "%dx%d", &width, &height) != 2) return std::cerr << "bad size\n", 2;
    if (argc > 2) rounds = std::max(1, std::atoi(argv[2]));
    const bool skipping = !(argc > 3 && std::string(argv[3]) == "--no-skipping");
    volren::registerPluginPath();
    osg::ref_ptr<osg::Node> scene = osgDB::readRefNodeFile(std::string(VOLREN_SOURCE_DIR) + "/scenes/default.osgt");
    if (!scene) return std::cerr << "cannot read scenes/default.osgt\n", 1;
    volren::OffscreenRenderer renderer(width, height);
    renderer.setScene(scene.get());
    const osg::BoundingSphere b = scene->getBound();
    const osg::Vec3d centre(b.center());
    renderer.camera()->setViewMatrix(
        osg::Matrixd::lookAt(centre + osg::Vec3d(0.55, 1, 0.35) * (3.2 * b.radius()), centre, osg::Vec3d(0, 0, 1)));
    renderer.camera()->setProjectionMatrixAsPerspective(30.0, double(width) / height, 1.0, 10.0 * b.radius());
    struct Finder : osg::NodeVisitor
    {
        Finder() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        volren::VolumeNode* node = nullptr;
        void apply(osg::Node& n) override
        {
            if (!node) node = dynamic_cast<volren::VolumeNode*>(&n);
            traverse(n);
        }
    } finder;
    scene->accept(finder);
    auto* tf = const_cast<volren::TransferFunction*>(finder.node->getTransferFunction());
    if (!skipping) finder.node->settings.forceNull.insert("Acceleration");
    for (int i = 0; i < 2; ++i) renderer.renderFrame();  // warm-up

    std::vector<double> edited, plain;
    for (int r = 0; r < rounds; ++r) {
        // An edit as a drag makes it: one control point's opacity changes.
        auto point = std::next(tf->points().begin(), long(tf->points().size() / 2));
        osg::Vec4 rgba = point->second;
        rgba.a() = r % 2 ? rgba.a() * 1.01f : rgba.a() / 1.01f;
        const auto start = std::chrono::steady_clock::now();
        tf->setPoint(point->first, rgba);
        renderer.renderFrame();
        edited.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        const auto again = std::chrono::steady_clock::now();
        renderer.renderFrame();
        plain.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - again).count());
    }
    std::vector<double> grid;
    const volren::Volume& volume = *finder.node->getVolume();
    for (int r = 0; r < rounds; ++r) {
        const auto start = std::chrono::steady_clock::now();
        const volren::MacrocellGrid g = volren::buildMacrocellGrid(volume, finder.node->settings.macrocellSize, 1);
        grid.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        if (g.size() == 0) return 1;
    }
    std::cout << "default scene " << width << "x" << height << ", " << rounds << " rounds, skipping "
              << (skipping ? "on" : "off") << " (" << renderer.contextDescription()
              << ")\nedit to screen (frame after an edit): " << median(edited) << " ms median\n"
              << "frame without an edit:               " << median(plain) << " ms median\n"
              << "macrocell grid build (CPU, once per volume of " << volume.voxelCount() << " voxels): " << median(grid)
              << " ms median\n";
    return 0;
}
