// --place's placements: parsed strictly, applied as scale, then rotation, then translation.
#include <volume_model/SceneInputs.h>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

void expectNear(const osg::Vec3d& got, const osg::Vec3d& want)
{
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-12) << "component " << i;
}

TEST(Placement, ScalesThenTurnsThenMoves)
{
    const Placement p = parsePlacement("10,20,30:2,3,4:z,90");
    expectNear(p.translation, {10, 20, 30});
    expectNear(p.scale, {2, 3, 4});
    expectNear(p.axis, {0, 0, 1});
    EXPECT_DOUBLE_EQ(p.angleDegrees, 90.0);
    // (1, 1, 1) -> scaled (2, 3, 4) -> turned 90 degrees about z (-3, 2, 4) -> moved (7, 22, 34).
    expectNear(osg::Vec3d(1, 1, 1) * p.matrix(), {7, 22, 34});
}

TEST(Placement, AcceptsEveryDocumentedForm)
{
    expectNear(parsePlacement("1,2,3").scale, {1, 1, 1});
    expectNear(parsePlacement("1,2,3:5").scale, {5, 5, 5});
    const Placement turnedOnly = parsePlacement("0,0,0:x,-90");
    expectNear(turnedOnly.scale, {1, 1, 1});
    expectNear(osg::Vec3d(0, 1, 0) * turnedOnly.matrix(), {0, 0, -1});
    const Placement anyAxis = parsePlacement("0,0,0:1:0,0,2,180");
    expectNear(osg::Vec3d(1, 0, 0) * anyAxis.matrix(), {-1, 0, 0});
    expectNear(osg::Vec3d(4, 5, 6) * parsePlacement("-1,0,1e3").matrix(), {3, 5, 1006});
}

TEST(Placement, RejectsWhatItCannotRead)
{
    for (const char* bad : {"", "1,2", "1,2,3,4", "a,b,c", "1,2,3:0", "1,2,3:-1,1,1", "1,2,3:1,2", "1,2,3:q,90",
                            "1,2,3:x,", "1,2,3:0,0,0,45", "1,2,3:1:x,90:2", "0,0,0:x,90:y,90", "nan,0,0", "1,2,3:inf"}) {
        EXPECT_THROW(parsePlacement(bad), std::invalid_argument) << "'" << bad << "'";
    }
}

}  // namespace
}  // namespace volren::test
