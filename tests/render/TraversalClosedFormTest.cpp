// The implementations the CPU reference does not model (it integrates emission-absorption of the
// post-classified TF only), each against a closed form on a small volume seen orthographically
// from +Z through voxel centres: MinIP, average, MIDA and gradient-magnitude MIP (with every
// Gradient), the threshold classification, the debug shading's views, and the jitters on a
// homogeneous slab (exp(-sigma L) whatever the sample positions).
#include "RenderFixture.h"

#include <cmath>
#include <random>

namespace volren::test {
namespace {

class TraversalClosedForm : public RenderFixture
{
protected:
    static constexpr int n = 8;  ///< voxels per axis; 8x8 pixels over the 8x8 face

    /// Float volume whose voxel (i,j,k) holds f(i,j,k).
    template <typename F>
    static osg::ref_ptr<Volume> field(F f)
    {
        osg::ref_ptr<Volume> v = new Volume;
        v->allocate(VoxelType::Float32, {n, n, n});
        auto* data = reinterpret_cast<float*>(v->data());
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) data[i + n * (j + n * k)] = float(f(i, j, k));
        v->dirty();
        return v;
    }

    /// Colour = window position (grey), opacity `alpha`, over the window [lo, hi].
    static osg::ref_ptr<TransferFunction> grey(double lo, double hi, float alpha = 1.0f)
    {
        osg::ref_ptr<TransferFunction> tf = new TransferFunction;
        tf->setPoint(lo, osg::Vec4(0, 0, 0, alpha));
        tf->setPoint(hi, osg::Vec4(1, 1, 1, alpha));
        tf->setResolution(4097);
        return tf;
    }

    /// `volume` drawn with `functions` (slot -> implementation), one sample per voxel along z at
    /// its centre, early termination off.
    static Pixels draw(Volume* volume, TransferFunction* tf, const std::map<std::string, std::string>& functions,
                       const std::map<std::string, std::string>& settings = {})
    {
        osg::ref_ptr<VolumeNode> node = volumeNode(volume, tf);
        for (const auto& [slot, name] : functions) node->settings.functions[slot] = name;
        node->settings.sampleDistanceFactor = 1.0;
        std::string error;
        EXPECT_TRUE(node->settings.set("earlyTermination", "1", error)) << error;
        for (const auto& [key, value] : settings) EXPECT_TRUE(node->settings.set(key, value, error)) << error;
        return renderOrthoFromPlusZ(node.get(), n, n, double(n));
    }
};

TEST_F(TraversalClosedForm, MinipOfEachColumnIsItsSmallestVoxel)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> noise(0.2, 1.0);
    std::vector<double> values(n * n * n);
    for (double& v : values) v = noise(rng);
    values[2 + n * (6 + n * 3)] = 0.01;  // one cold voxel
    osg::ref_ptr<Volume> volume = field([&](int i, int j, int k) { return values[i + n * (j + n * k)]; });
    for (const char* reconstruction : {"nearest", "trilinear"}) {
        const Pixels img = draw(volume.get(), grey(0, 1).get(), {{"RayTraversal", "minip"}, {"Reconstruction", reconstruction}});
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                double expected = 1.0;
                for (int z = 0; z < n; ++z) expected = std::min(expected, values[x + n * (y + n * z)]);
                ASSERT_NEAR(img.at(x, y).r(), expected, 2e-4) << reconstruction << " " << x << "," << y;
                ASSERT_NEAR(img.at(x, y).a(), 1.0, 1e-6);
            }
        EXPECT_NEAR(img.at(2, 6).r(), 0.01, 2e-4);
    }
}

TEST_F(TraversalClosedForm, AverageOfEachColumnIsTheMeanOfItsVoxels)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(0.0, 1.0);
    std::vector<double> values(n * n * n);
    for (double& v : values) v = noise(rng);
    osg::ref_ptr<Volume> volume = field([&](int i, int j, int k) { return values[i + n * (j + n * k)]; });
    // Nearest: each unit segment holds one voxel's value, so the length-weighted mean is the
    // column's mean.
    const Pixels img = draw(volume.get(), grey(0, 1).get(), {{"RayTraversal", "average"}, {"Reconstruction", "nearest"}});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double mean = 0.0;
            for (int z = 0; z < n; ++z) mean += values[x + n * (y + n * z)] / n;
            ASSERT_NEAR(img.at(x, y).r(), mean, 2e-4) << x << "," << y;
        }
}

TEST_F(TraversalClosedForm, MidaAttenuatesWhatLiesInFrontOfANewMaximum)
{
    // Each column: its front half (seen first from +Z: k >= 4) at value a, its back half at b.
    // Bruckner & Groeller's accumulation, front to back over unit segments of opacity alpha
    // (per smallest spacing: one segment) and colour = value:
    //   delta = max(u - max so far, 0), beta = 1 - delta,
    //   C = beta C + (1 - beta A) alpha c,  A = beta A + (1 - beta A) alpha.
    const double alpha = 0.3;
    auto column = [](int x, int y, int k) { return k >= n / 2 ? 0.1 + 0.05 * x : 0.2 + 0.1 * y; };
    osg::ref_ptr<Volume> volume = field(column);
    const Pixels img = draw(volume.get(), grey(0, 1, float(alpha)).get(), {{"RayTraversal", "mida"}, {"Reconstruction", "nearest"}});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double c = 0.0, a = 0.0, maximum = 0.0;
            for (int k = n - 1; k >= 0; --k) {
                const double u = column(x, y, k);
                const double beta = 1.0 - std::max(u - maximum, 0.0);
                maximum = std::max(maximum, u);
                c = beta * c + (1.0 - beta * a) * alpha * u;
                a = beta * a + (1.0 - beta * a) * alpha;
            }
            ASSERT_NEAR(img.at(x, y).r(), c, 2e-3) << x << "," << y;
            ASSERT_NEAR(img.at(x, y).a(), a, 2e-3) << x << "," << y;
        }
    // Where the back is brighter, what lies in front is attenuated: less than plain DVR.
    EXPECT_LT(img.at(0, 7).a(), 1.0 - std::pow(1.0 - alpha, n) - 0.05);
}

TEST_F(TraversalClosedForm, GradientMipOfALinearRampIsItsSlopeWithEveryGradient)
{
    // v = 0.06 i: the gradient magnitude is 0.06 of the window [0,1] per voxel everywhere inside
    // (every difference formula is exact on a linear field); gmip looks it up in the window
    // as a fraction of the window per smallest spacing.
    osg::ref_ptr<Volume> volume = field([](int i, int, int) { return 0.06 * i; });
    for (const char* gradient : {"forward", "backward", "central", "central9"}) {
        const Pixels img =
            draw(volume.get(), grey(0, 1).get(),
                 {{"RayTraversal", "gmip"}, {"Gradient", gradient}, {"GradientInput", "scalar"}, {"Reconstruction", "trilinear"}});
        for (int y = 0; y < n; ++y)
            for (int x = 2; x < n - 2; ++x)  // two voxels from the x faces, where the field is clamped
                ASSERT_NEAR(img.at(x, y).r(), 0.06, 2e-3) << gradient << " " << x << "," << y;
    }
}

TEST_F(TraversalClosedForm, AlphaGradientInputDifferentiatesTheTfOpacityNotTheScalar)
{
    // v = 0.06 i under a white TF whose opacity is v / 2: the opacity's gradient is 0.03 per
    // voxel, the scalar's 0.06; gmip looks each magnitude up in the TF (premultiplied: white
    // times the opacity there), so alpha gives 0.03 / 2 and scalar 0.06 / 2.
    osg::ref_ptr<Volume> volume = field([](int i, int, int) { return 0.06 * i; });
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(1, 1, 1, 0.0f));
    tf->setPoint(1.0, osg::Vec4(1, 1, 1, 0.5f));
    tf->setResolution(4097);
    for (const auto& [input, expected] : {std::pair{"alpha", 0.015}, std::pair{"scalar", 0.03}}) {
        const Pixels img = draw(volume.get(), tf.get(),
                                {{"RayTraversal", "gmip"}, {"Gradient", "central"}, {"GradientInput", input}, {"Reconstruction", "trilinear"}});
        for (int y = 0; y < n; ++y)
            for (int x = 2; x < n - 2; ++x) ASSERT_NEAR(img.at(x, y).r(), expected, 1e-3) << input << " " << x << "," << y;
    }
}

TEST_F(TraversalClosedForm, NullClassificationIsAGreyRampOfTheWindowPosition)
{
    // Without a TF the classification is (u, u, u, u) for window position u: a homogeneous slab
    // of u = 0.25, n voxels thick, has opacity 1 - (1 - u)^n and premultiplied colour u times it.
    osg::ref_ptr<Volume> volume = field([](int, int, int) { return 0.25; });
    const Pixels img = draw(volume.get(), grey(0, 1).get(), {{"Classification", "null"}, {"Reconstruction", "trilinear"}});
    const double alpha = 1.0 - std::pow(1.0 - 0.25, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            ASSERT_NEAR(img.at(x, y).a(), alpha, 2e-3) << x << "," << y;
            ASSERT_NEAR(img.at(x, y).g(), 0.25 * alpha, 2e-3) << x << "," << y;
        }
}

TEST_F(TraversalClosedForm, ThresholdClassificationIsOpaqueTfColourAboveItsLevelAndEmptyBelow)
{
    // Columns x < 4 hold 0.3, the others 0.7 of the window; threshold 0.5: the first sample of a
    // column above it is opaque with the TF colour at its value, below nothing at all.
    osg::ref_ptr<Volume> volume = field([](int i, int, int) { return i < n / 2 ? 0.3 : 0.7; });
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(0.0f, 1.0f, 0.0f, 0.05f));
    tf->setPoint(1.0, osg::Vec4(1.0f, 0.0f, 0.5f, 0.05f));
    tf->setResolution(4097);
    const Pixels img = draw(volume.get(), tf.get(), {{"Classification", "threshold"}, {"Reconstruction", "nearest"}},
                            {{"threshold", "0.5"}});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const osg::Vec4 expected = x < n / 2 ? osg::Vec4(0, 0, 0, 0) : osg::Vec4(0.7f, 0.3f, 0.35f, 1.0f);
            for (int c = 0; c < 4; ++c) ASSERT_NEAR(img.at(x, y)[c], expected[c], 2e-3) << x << "," << y << " channel " << c;
        }
}

TEST_F(TraversalClosedForm, DebugShadingShowsTheScalarAndThePositionOfTheFirstSample)
{
    // An opaque TF: each pixel shows its column's first sample (the top voxel's centre, k = 7).
    osg::ref_ptr<Volume> volume = field([](int i, int j, int) { return 0.05 + 0.1 * i + 0.01 * j; });
    const std::map<std::string, std::string> functions = {{"Shading", "debug"}, {"Reconstruction", "nearest"}};
    const Pixels scalar = draw(volume.get(), grey(0, 1).get(), functions, {{"debugView", "scalar"}});
    const Pixels position = draw(volume.get(), grey(0, 1).get(), functions, {{"debugView", "position"}});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            ASSERT_NEAR(scalar.at(x, y).r(), 0.05 + 0.1 * x + 0.01 * y, 1e-4) << x << "," << y;
            ASSERT_NEAR(position.at(x, y).r(), (x + 0.5) / n, 1e-4) << x << "," << y;
            ASSERT_NEAR(position.at(x, y).g(), (y + 0.5) / n, 1e-4) << x << "," << y;
            ASSERT_NEAR(position.at(x, y).b(), (n - 0.5) / n, 1e-4) << x << "," << y;
        }
}

TEST_F(TraversalClosedForm, EveryJitterLeavesAHomogeneousSlabAtItsClosedForm)
{
    // A homogeneous slab n voxels thick of TF opacity alpha per voxel: 1 - (1 - alpha)^n whatever
    // the samples' offsets (every segment has the same extinction), colour premultiplied.
    const double alpha = 0.2;
    osg::ref_ptr<Volume> volume = field([](int, int, int) { return 0.5; });
    const double expected = 1.0 - std::pow(1.0 - alpha, n);
    for (const char* jitter : {"null", "hash", "texture"}) {
        const Pixels img = draw(volume.get(), grey(0, 1, float(alpha)).get(), {{"Jitter", jitter}, {"Reconstruction", "trilinear"}});
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                ASSERT_NEAR(img.at(x, y).a(), expected, 2e-3) << jitter << " " << x << "," << y;
                ASSERT_NEAR(img.at(x, y).r(), 0.5 * expected, 2e-3) << jitter << " " << x << "," << y;
            }
    }
}

}  // namespace
}  // namespace volren::test
