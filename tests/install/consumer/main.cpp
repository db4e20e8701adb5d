// Reads a volume with the installed osgdb plugin and renders it headlessly with the installed
// shaders; prints the centre pixel and fails unless the volume is visible there.
#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_renderer/OffscreenRenderer.h>

#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 2) return 2;
    try {
        osg::ref_ptr<volren::Volume> volume = volren::readVolumeFile(argv[1]);
        osg::ref_ptr<osg::Group> scene = volren::makeDefaultScene(volume.get());
        volren::OffscreenRenderer renderer(64, 64);
        renderer.setScene(scene.get());
        const double r = scene->getBound().radius();
        renderer.camera()->setViewMatrixAsLookAt(osg::Vec3d(0, 4 * r, 0), osg::Vec3d(), osg::Vec3d(0, 0, 1));
        renderer.renderFrame();
        const float* rgba = reinterpret_cast<const float*>(renderer.image()->data(32, 32));
        std::cout << "share: " << volren::shareDirectory() << "\ncentre alpha: " << rgba[3] << std::endl;
        return rgba[3] > 0.1f ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "consumer: " << e.what() << std::endl;
        return 1;
    }
}
