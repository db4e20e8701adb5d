#pragma once
#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>
#include <volume_model/VolumeNode.h>

#include <osgDB/Options>

#include <initializer_list>
#include <string>
#include <utility>

namespace volren::test {

/// Whether ../shared/data is present; its absence is a test failure when
/// $VOLREN_REQUIRE_SHARED_DATA is set (CI sets it).
bool sharedDataPresent();

/// Path of a file in ../shared/data (see its MANIFEST.md).
std::string sharedData(const std::string& relative);

/// Skips the calling test when ../shared/data is absent (fails instead under CI).
#define VOLREN_REQUIRE_SHARED_DATA() \
    if (!::volren::test::sharedDataPresent()) GTEST_SKIP() << "../shared/data is not present"

/// A fresh empty temporary directory for this test.
std::string tempDirectory();

/// A volume of `dims` whose every voxel stores `value`.
osg::ref_ptr<Volume> constantVolume(VoxelType type, const osg::Vec3i& dims, double value,
                                    const osg::Vec3d& spacing = {1.0, 1.0, 1.0});

/// Writes `bytes` to `path` (binary).
void writeFile(const std::string& path, const std::string& bytes);

/// Writes `bytes` as `name` in this test's temporary directory and expects readVolumeFile to
/// reject it with a message naming the file and containing `reason`.
void expectRejected(const std::string& name, const std::string& bytes, const std::string& reason);

/// The message of readVolumeFile's error for `path`; a test failure when it reads fine.
std::string expectReadError(const std::string& path, const osgDB::Options* options = nullptr);

/// A TF with the same colour and opacity everywhere on [lo, hi].
osg::ref_ptr<TransferFunction> constantTransferFunction(const osg::Vec4& rgba, double lo = 0.0, double hi = 255.0);

/// A TF of these control points with the value window [lo, hi].
osg::ref_ptr<TransferFunction> transferFunction(std::initializer_list<std::pair<double, osg::Vec4>> points, double lo,
                                                double hi);

/// A VolumeNode showing `volume` through `tf`, jitter off unless asked.
osg::ref_ptr<VolumeNode> makeVolumeNode(Volume* volume, TransferFunction* tf, bool jitter = false);

}  // namespace volren::test
