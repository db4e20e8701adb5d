#include "TestData.h"

#include <volume_model/ReadVolume.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace volren::test {

bool sharedDataPresent()
{
    if (std::filesystem::exists(std::filesystem::path(VOLREN_SHARED_DATA) / "MANIFEST.md")) return true;
    if (std::getenv("VOLREN_REQUIRE_SHARED_DATA")) {
        ADD_FAILURE() << "shared datasets missing at " << VOLREN_SHARED_DATA;
        return true;  // let the test run on and fail on the missing files as well
    }
    return false;
}

std::string sharedData(const std::string& relative)
{
    const std::filesystem::path path = std::filesystem::path(VOLREN_SHARED_DATA) / relative;
    if (!std::filesystem::exists(path)) ADD_FAILURE() << "shared dataset missing: " << path;
    return path.string();
}

std::string tempDirectory()
{
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("volren-") + info->test_suite_name() + "-" + info->name();
    // The render suite runs again in a core profile (ctest -j runs both at once): apart.
    if (const char* profile = std::getenv("VOLREN_GL_PROFILE"); profile && *profile) name += std::string("-") + profile;
    for (char& c : name)
        if (c == '/') c = '_';
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

osg::ref_ptr<Volume> constantVolume(VoxelType type, const osg::Vec3i& dims, double value, const osg::Vec3d& spacing)
{
    osg::ref_ptr<Volume> v = new Volume;
    v->allocate(type, dims);
    v->setSpacing(spacing);
    const std::size_t n = v->voxelCount();
    for (std::size_t i = 0; i < n; ++i) {
        switch (type) {
        case VoxelType::UInt8: v->data()[i] = std::uint8_t(value); break;
        case VoxelType::Int8: v->data()[i] = std::uint8_t(std::int8_t(value)); break;
        case VoxelType::UInt16: { const auto s = std::uint16_t(value); std::memcpy(v->data() + 2 * i, &s, 2); break; }
        case VoxelType::Int16: { const auto s = std::int16_t(value); std::memcpy(v->data() + 2 * i, &s, 2); break; }
        case VoxelType::Float32: { const auto f = float(value); std::memcpy(v->data() + 4 * i, &f, 4); break; }
        }
    }
    v->dirty();
    return v;
}

void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

void expectRejected(const std::string& name, const std::string& bytes, const std::string& reason)
{
    const std::string path = tempDirectory() + "/" + name;
    writeFile(path, bytes);
    const std::string why = expectReadError(path);
    EXPECT_NE(why.find(path), std::string::npos) << why;
    EXPECT_NE(why.find(reason), std::string::npos) << name << ": " << why;
}

std::string expectReadError(const std::string& path, const osgDB::Options* options)
{
    try {
        readVolumeFile(path, options);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected " << path << " to be rejected";
    return {};
}

osg::ref_ptr<TransferFunction> constantTransferFunction(const osg::Vec4& rgba, double lo, double hi)
{
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(lo, rgba);
    tf->setPoint(hi, rgba);
    return tf;
}

osg::ref_ptr<TransferFunction> transferFunction(std::initializer_list<std::pair<double, osg::Vec4>> points, double lo,
                                                double hi)
{
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    for (const auto& [value, rgba] : points) tf->setPoint(value, rgba);
    tf->setDomain(lo, hi);
    return tf;
}

osg::ref_ptr<VolumeNode> makeVolumeNode(Volume* volume, TransferFunction* tf, bool jitter)
{
    osg::ref_ptr<VolumeNode> node = new VolumeNode;
    node->setVolume(volume);
    node->setTransferFunction(tf);
    node->settings.functions["Jitter"] = jitter ? "hash" : "null";
    return node;
}

}  // namespace volren::test
