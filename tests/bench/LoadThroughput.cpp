// Load throughput of the volume readers against a plain read of the same bytes, side by side:
//   load_throughput FILE [ROUNDS]
// Each round reads FILE once with std::fread into a buffer of its size (the floor any reader
// pays) and once through volren::readVolumeFile; the page cache is warm after the first round.
// Prints MB/s of both and their ratio (medians over the rounds).
#include <volume_model/ReadVolume.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double seconds(const std::chrono::steady_clock::time_point& start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::cerr << "usage: load_throughput FILE [ROUNDS]\n";
        return 2;
    }
    const std::string path = argv[1];
    const int rounds = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
    std::vector<double> plain, reader;
    double fileBytes = 0.0, voxelBytes = 0.0;
    try {
        for (int r = 0; r < rounds; ++r) {
            auto start = std::chrono::steady_clock::now();
            std::FILE* f = std::fopen(path.c_str(), "rb");
            if (!f) throw std::runtime_error(path + ": cannot open");
            std::fseek(f, 0, SEEK_END);
            std::vector<char> bytes(std::size_t(std::ftell(f)));
            std::fseek(f, 0, SEEK_SET);
            const std::size_t got = std::fread(bytes.data(), 1, bytes.size(), f);
            std::fclose(f);
            plain.push_back(seconds(start));
            fileBytes = double(got);

            start = std::chrono::steady_clock::now();
            osg::ref_ptr<volren::Volume> volume = volren::readVolumeFile(path);
            reader.push_back(seconds(start));
            voxelBytes = double(volume->byteSize());
        }
    } catch (const std::exception& e) {
        std::cerr << "load_throughput: " << e.what() << "\n";
        return 1;
    }
    const double p = median(plain), v = median(reader);
    std::cout << path << ": " << fileBytes / 1e6 << " MB on disk, " << voxelBytes / 1e6 << " MB of voxels, "
              << rounds << " rounds\n"
              << "  plain read:     " << p * 1e3 << " ms  (" << fileBytes / 1e6 / p << " MB/s of file)\n"
              << "  readVolumeFile: " << v * 1e3 << " ms  (" << fileBytes / 1e6 / v << " MB/s of file, "
              << voxelBytes / 1e6 / v << " MB/s of voxels)\n"
              << "  reader / plain time: " << v / p << "\n";
    return 0;
}
