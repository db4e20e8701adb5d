// A homogeneous slab seen head-on must transmit exactly (1 - alpha)^(L / d0) = exp(-sigma L)
// at any sample distance: this checks the opacity correction for the actual step.
#include "RenderFixture.h"
#include "TestData.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace volren::test {
namespace {

struct SlabCase
{
    double sampleFactor;  ///< step as a factor of the smallest spacing
    double alpha;         ///< TF opacity per smallest spacing
    osg::Vec3d spacing;   ///< voxel spacing
};

void PrintTo(const SlabCase& c, std::ostream* out)
{
    *out << "step " << c.sampleFactor << " x d0, alpha " << c.alpha << ", spacing " << c.spacing.x() << ","
         << c.spacing.y() << "," << c.spacing.z();
}

std::string caseName(const ::testing::TestParamInfo<SlabCase>& info)
{
    auto clean = [](double v) {
        std::string s = std::to_string(v);
        s.erase(s.find_last_not_of('0') + 1);
        for (char& c : s)
            if (c == '.' || c == '-') c = '_';
        return s;
    };
    return "step" + clean(info.param.sampleFactor) + "_alpha" + clean(info.param.alpha) + "_dz" +
           clean(info.param.spacing.z());
}

class SlabTransmittance : public RenderFixture, public ::testing::WithParamInterface<SlabCase>
{
};

TEST_P(SlabTransmittance, EqualsBeerLambertAtAnyStep)
{
    const SlabCase c = GetParam();
    const osg::Vec3i dims(8, 8, 40);
    osg::ref_ptr<Volume> volume = constantVolume(VoxelType::UInt8, dims, 100, c.spacing);
    osg::ref_ptr<TransferFunction> tf = constantTransferFunction(osg::Vec4(1, 1, 1, float(c.alpha)));
    osg::ref_ptr<VolumeNode> node = volumeNode(volume.get(), tf.get());
    node->settings.sampleDistanceFactor = c.sampleFactor;
    node->settings.earlyTerminationThreshold = 1.0;

    // The box is 8*sx wide; a 16-pixel view of 16*sx world units puts it on pixels 4..11.
    const Pixels img = renderOrthoFromPlusZ(node.get(), 16, 16, 16.0 * c.spacing.y());

    const double length = dims.z() * c.spacing.z();
    const double reference = std::min({c.spacing.x(), c.spacing.y(), c.spacing.z()});
    const double expected = -std::expm1(length / reference * std::log1p(-c.alpha));  // 1 - (1-a)^(L/d0)
    // float32 GPU arithmetic; measured worst case 1.3e-6. Tight enough that alpha = 1e-7
    // (expected 4e-6) fails if the tiny opacity is lost.
    const double tolerance = 2e-7 + 1e-4 * expected;
    double worst = 0.0;
    for (int y = 5; y <= 10; ++y)
        for (int x = 5; x <= 10; ++x) {
            const osg::Vec4& p = img.at(x, y);
            worst = std::max({worst, std::abs(p.a() - expected), std::abs(p.r() - expected)});
            ASSERT_NEAR(p.a(), expected, tolerance) << "pixel " << x << "," << y;
            ASSERT_NEAR(p.r(), expected, tolerance) << "pixel " << x << "," << y;
        }
    RecordProperty("expected", std::to_string(expected));
    std::ostringstream error;
    error << std::scientific << std::setprecision(2) << worst;
    RecordProperty("max_abs_error", error.str());
    for (int y = 0; y < 16; ++y)
        for (int x : {0, 1, 2, 13, 14, 15}) ASSERT_EQ(img.at(x, y), osg::Vec4(0, 0, 0, 0)) << "outside " << x << "," << y;
}

INSTANTIATE_TEST_SUITE_P(StepFactors, SlabTransmittance,
                         ::testing::Values(SlabCase{0.001, 0.05, {1, 1, 1}},  // 1/1000 voxel: 40000 steps
                                           SlabCase{0.01, 0.05, {1, 1, 1}},
                                           SlabCase{0.37, 0.05, {1, 1, 1}},
                                           SlabCase{1.0, 0.05, {1, 1, 1}},
                                           SlabCase{2.5, 0.05, {1, 1, 1}},
                                           SlabCase{13.0, 0.05, {1, 1, 1}},
                                           SlabCase{100.0, 0.05, {1, 1, 1}}),  // one step spans the slab
                         caseName);

INSTANTIATE_TEST_SUITE_P(ExtremeOpacities, SlabTransmittance,
                         ::testing::Values(SlabCase{0.5, 1e-7, {1, 1, 1}},  // log1p/expm1 keep the digits
                                           SlabCase{0.001, 1e-4, {1, 1, 1}},
                                           SlabCase{0.5, 0.999, {1, 1, 1}},
                                           SlabCase{100.0, 0.3, {1, 1, 1}}),
                         caseName);

INSTANTIATE_TEST_SUITE_P(AnisotropicSpacing, SlabTransmittance,
                         ::testing::Values(SlabCase{0.5, 0.02, {0.5, 0.5, 2.0}},  // d0 = 0.5, L = 80
                                           SlabCase{3.0, 0.02, {1.0, 1.0, 0.25}}),
                         caseName);

}  // namespace
}  // namespace volren::test
