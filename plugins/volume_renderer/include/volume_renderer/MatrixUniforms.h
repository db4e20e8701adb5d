#pragma once
#include <osg/Drawable>

namespace volren {

/// Draw callback for GLSL drawables (the volume proxies, and any of yours): feeds `osg_ModelViewProjectionMatrix` to the current
/// program when the context's osg::State does not (OSG's uniform mode is off, as in stock
/// `osgviewer` and most applications with a compatibility context). volren's own contexts turn
/// the uniform mode on; then this callback only draws. The shaders read the vertex from
/// attribute 0, which is the fixed-function vertex array in a compatibility context.
/// Drawn from client arrays (no VAO), it unbinds any vertex buffer first and makes OSG forget
/// those arrays afterwards (see forgetBoundVertexBuffer, forgetClientArrays).
class MatrixUniforms : public osg::Drawable::DrawCallback
{
public:
    void drawImplementation(osg::RenderInfo& renderInfo, const osg::Drawable* drawable) const override;
};

/// Unbinds GL_ARRAY_BUFFER and tells the current vertex-array state so. GL_ARRAY_BUFFER is
/// context state, but OSG 3.6 tracks it per vertex-array state: after a drawable with a VAO
/// (and its vertex buffer) in a compatibility context, the global state believes nothing is
/// bound while that buffer still is, and client array addresses become offsets into it (the
/// volume proxies of a scene that gains a VAO model after its first frame drew nothing).
void forgetBoundVertexBuffer(osg::State& state);

/// Disables the client arrays OSG's global vertex-array state holds and forgets their addresses.
/// OSG 3.6 skips glVertexPointer when an array has the address and modified count of the one
/// it set last, even across frames, and State::reset() does not clear that; so a new scene's
/// array allocated where the last scene's was freed would be drawn from freed memory.
void forgetClientArrays(osg::State& state);

}  // namespace volren
