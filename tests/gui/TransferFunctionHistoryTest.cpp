#include <volume_gui/TransferFunctionHistory.h>

#include <gtest/gtest.h>

namespace volren::test {
namespace {

TEST(TransferFunctionHistory, UndoAndRedoRestoreTheModelInPlace)
{
    osg::ref_ptr<TransferFunction> tf = new TransferFunction;
    tf->setPoint(0.0, osg::Vec4(0, 0, 0, 0));
    TransferFunctionHistory history(tf.get());
    EXPECT_FALSE(history.canUndo());

    tf->setPoint(5.0, osg::Vec4(1, 0, 0, 0.5f));
    history.record();
    tf->setDomain(-1.0, 9.0);
    history.record();
    const TransferFunction::Points twoPoints = tf->points();

    ASSERT_TRUE(history.undo());
    EXPECT_FALSE(tf->hasExplicitDomain());
    EXPECT_EQ(tf->points(), twoPoints);
    ASSERT_TRUE(history.undo());
    EXPECT_EQ(tf->points().size(), 1u);
    EXPECT_FALSE(history.undo());

    const unsigned before = tf->modifiedCount();
    ASSERT_TRUE(history.redo());
    EXPECT_GT(tf->modifiedCount(), before) << "the renderer must notice";
    ASSERT_TRUE(history.redo());
    EXPECT_DOUBLE_EQ(tf->domainMin(), -1.0);
    EXPECT_FALSE(history.redo());

    // A new edit after an undo drops the redo branch.
    history.undo();
    tf->setPoint(7.0, osg::Vec4(0, 1, 0, 1));
    history.record();
    EXPECT_FALSE(history.canRedo());
}

}  // namespace
}  // namespace volren::test
