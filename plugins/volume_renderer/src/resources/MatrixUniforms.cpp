#include <volume_renderer/MatrixUniforms.h>

#include <osg/GLExtensions>
#include <osg/Program>
#include <osg/State>
#include <osg/Uniform>

namespace volren {

void MatrixUniforms::drawImplementation(osg::RenderInfo& renderInfo, const osg::Drawable* drawable) const
{
    osg::State& state = *renderInfo.getState();
    if (!state.getUseModelViewAndProjectionUniforms()) {
        static const unsigned int mvpName = osg::Uniform::getNameID("osg_ModelViewProjectionMatrix");
        if (const osg::Program::PerContextProgram* pcp = state.getLastAppliedProgramObject()) {
            const GLint location = pcp->getUniformLocation(mvpName);
            if (location >= 0) {
                const osg::Matrixf mvp(state.getModelViewMatrix() * state.getProjectionMatrix());
                state.get<osg::GLExtensions>()->glUniformMatrix4fv(location, 1, GL_FALSE, mvp.ptr());
            }
        }
    }
    const bool clientArrays = !state.useVertexArrayObject(drawable->getUseVertexArrayObject());
    if (clientArrays) forgetBoundVertexBuffer(state);
    drawable->drawImplementation(renderInfo);
    if (clientArrays) forgetClientArrays(state);
}

void forgetBoundVertexBuffer(osg::State& state)
{
    state.get<osg::GLExtensions>()->glBindBuffer(GL_ARRAY_BUFFER_ARB, 0);
    state.setCurrentVertexBufferObject(nullptr);
}

void forgetClientArrays(osg::State& state)
{
    if (!state.getCurrentVertexArrayState()) return;
    state.lazyDisablingOfVertexAttributes();  // marks every array in use as unused...
    state.applyDisablingOfVertexAttributes();  // ...then disables them and forgets their addresses
}

}  // namespace volren
