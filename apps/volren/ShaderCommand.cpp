#include "Commands.h"
#include "SceneSetup.h"

#include <volume_renderer/OffscreenRenderer.h>

#include <iostream>

namespace volren::app {

int shaderCommand(const std::vector<std::string>& args)
{
    RenderOptions options = parseRenderOptions(args, false);
    options.width = options.height = 16;  // the analysis needs a frame, not a picture
    osg::ref_ptr<VolumeScene> scene = loadScene(options);
    OffscreenRenderer renderer(options.width, options.height);
    renderer.setScene(scene.get());
    setUpCamera(*renderer.camera(), *scene, options, 1.0);
    renderer.renderFrame();
    const auto programs = scene->programs();
    if (programs.empty()) throw std::runtime_error("the scene shows no volume, so there is no ray caster to print");
    for (const auto& [name, program] : programs) {
        std::cout << "// ===== volume: " << name << "\n// ===== key: " << program->key << "\n"
                  << program->fragmentSource << "\n";
    }
    return 0;
}

}  // namespace volren::app
