#pragma once
// Running the real `volren` binary from tests, and reading the images it writes.
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace volren::test {

struct CliRun
{
    int exitCode = -1;
    std::string output;  // stdout and stderr
};

inline CliRun volren(const std::string& args, const std::string& workingDirectory = ".", const std::string& env = "")
{
    const std::string command = "cd '" + workingDirectory + "' && " + env + "'" + std::string(VOLREN_BINARY_DIR) +
                                "/bin/volren' " + args + " 2>&1";
    CliRun run;
    FILE* pipe = popen(command.c_str(), "r");
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof(buf), pipe)) > 0) run.output.append(buf, n);
    const int status = pclose(pipe);
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

struct Image
{
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;  // top row first
    float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

inline Image readImage(const std::string& path)
{
    Image img;
    auto in = OIIO::ImageInput::open(path);
    if (!in) return img;
    const OIIO::ImageSpec& spec = in->spec();
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.nchannels;
    img.pixels.resize(std::size_t(img.width) * img.height * img.channels);
    in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.pixels.data());
    return img;
}

/// Pixels of `img` whose alpha exceeds `alpha`.
inline float coveredPixels(const Image& img, float alpha = 0.05f)
{
    float covered = 0.0f;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) covered += img.at(x, y, 3) > alpha;
    return covered;
}

}  // namespace volren::test
