// LightDrag: Ctrl + drag turns the scene's lights about the view's axes (closed forms: a quarter
// turn for a drag over half the window).
#include <volume_gui/LightDrag.h>

#include <gtest/gtest.h>

#include <osg/Geode>
#include <osg/Group>
#include <osg/MatrixTransform>
#include <osg/ShapeDrawable>

namespace volren::test {
namespace {

struct NoActions : osgGA::GUIActionAdapter
{
    void requestRedraw() override {}
    void requestContinuousUpdate(bool) override {}
    void requestWarpPointer(float, float) override {}
};

osg::ref_ptr<osgGA::GUIEventAdapter> drag(osgGA::GUIEventAdapter::EventType type, float x, float y, bool ctrl = true)
{
    osg::ref_ptr<osgGA::GUIEventAdapter> e = new osgGA::GUIEventAdapter;
    e->setEventType(type);
    e->setWindowRectangle(0, 0, 200, 100);
    e->setInputRange(-1, -1, 1, 1);  // x and y are the normalised coordinates themselves
    e->setX(x);
    e->setY(y);
    e->setButton(osgGA::GUIEventAdapter::LEFT_MOUSE_BUTTON);
    e->setModKeyMask(ctrl ? osgGA::GUIEventAdapter::MODKEY_LEFT_CTRL : 0);
    e->setMouseYOrientation(osgGA::GUIEventAdapter::Y_INCREASING_UPWARDS);  // as osgViewer's windows send them
    return e;
}

void expectNear(const osg::Vec4& a, const osg::Vec4d& b, const char* what)
{
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], 1e-5) << what << " component " << i;
}

TEST(LightDrag, HalfTheWindowTurnsAHeadlightAQuarterTurnTowardsTheDrag)
{
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    osg::ref_ptr<osg::LightSource> headlight = new osg::LightSource;
    headlight->setReferenceFrame(osg::LightSource::ABSOLUTE_RF);
    headlight->getLight()->setPosition({0, 0, 1, 0});
    scene->addChild(headlight.get());
    osg::ref_ptr<osg::Camera> camera = new osg::Camera;
    camera->setViewMatrixAsLookAt({3, -40, 7}, {3, 0, 7}, {0, 0, 1});
    osg::ref_ptr<LightDrag> handler = new LightDrag(scene.get(), camera.get());
    NoActions actions;
    EXPECT_FALSE(handler->handle(*drag(osgGA::GUIEventAdapter::PUSH, 0, 0, false), actions)) << "without Ctrl: the camera's";
    EXPECT_TRUE(handler->handle(*drag(osgGA::GUIEventAdapter::PUSH, -0.5f, 0), actions));
    EXPECT_TRUE(handler->handle(*drag(osgGA::GUIEventAdapter::DRAG, 0.5f, 0), actions));
    expectNear(headlight->getLight()->getPosition(), {1, 0, 0, 0}, "dragged right: from the right (eye x)");
    EXPECT_TRUE(handler->handle(*drag(osgGA::GUIEventAdapter::DRAG, -0.5f, 1.0f), actions));
    expectNear(headlight->getLight()->getPosition(), {0, 1, 0, 0}, "dragged up: from above (eye y)");
    EXPECT_TRUE(handler->handle(*drag(osgGA::GUIEventAdapter::RELEASE, -0.5f, 1.0f), actions));
    EXPECT_FALSE(handler->handle(*drag(osgGA::GUIEventAdapter::DRAG, 0.9f, 0.9f), actions)) << "released";
}

TEST(LightDrag, APointLightUnderATransformCirclesTheSceneCentre)
{
    // The scene: a unit box at world (0, 0, 0) and a point light 10 above it, under a transform
    // that shifts it by (5, 0, 0) (its local position is (-5, 0, 10)).
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    osg::ref_ptr<osg::Geode> box = new osg::Geode;
    box->addDrawable(new osg::ShapeDrawable(new osg::Box(osg::Vec3(), 1.0f)));
    scene->addChild(box.get());
    osg::ref_ptr<osg::MatrixTransform> shift = new osg::MatrixTransform(osg::Matrix::translate(5, 0, 0));
    osg::ref_ptr<osg::LightSource> lamp = new osg::LightSource;
    lamp->getLight()->setPosition({-5, 0, 10, 1});
    shift->addChild(lamp.get());
    scene->addChild(shift.get());
    osg::ref_ptr<osg::Camera> camera = new osg::Camera;
    camera->setViewMatrixAsLookAt({0, -30, 0}, {0, 0, 0}, {0, 0, 1});  // eye x = world x, eye y = world z
    osg::ref_ptr<LightDrag> handler = new LightDrag(scene.get(), camera.get());
    NoActions actions;
    handler->handle(*drag(osgGA::GUIEventAdapter::PUSH, 0, 0), actions);
    // Dragging down by half the window turns it a quarter about the eye's x axis, away from the
    // viewer's up: the light at world (0, 0, 10) goes to world (0, -10, 0), towards the camera.
    handler->handle(*drag(osgGA::GUIEventAdapter::DRAG, 0, -1.0f), actions);
    expectNear(lamp->getLight()->getPosition(), {-5, -10, 0, 1}, "local coordinates after a quarter turn");
    // Down by the whole window from the start: half a turn, the far side, world (0, 0, -10).
    handler->handle(*drag(osgGA::GUIEventAdapter::DRAG, 0, -2.0f), actions);
    expectNear(lamp->getLight()->getPosition(), {-5, 0, -10, 1}, "half a turn");
}

TEST(LightDrag, TurnedKeepsDirectionsUnitAndIgnoresThePivot)
{
    const osg::Matrixd r = LightDrag::eyeRotation(0.3, -0.7);
    const osg::Vec4d d = LightDrag::turned({0.6, 0, 0.8, 0}, osg::Matrixd::translate(4, 5, 6), r, {100, 0, 0});
    EXPECT_NEAR(osg::Vec3d(d.x(), d.y(), d.z()).length(), 1.0, 1e-12);
    EXPECT_EQ(d.w(), 0.0);
    const osg::Vec4d same = LightDrag::turned({0.6, 0, 0.8, 0}, osg::Matrixd(), r, {});
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(d[i], same[i], 1e-12);
}

}  // namespace
}  // namespace volren::test
