#pragma once
#include <osg/Drawable>

namespace volren {

/// Draw callback for GLSL drawables (the volume proxies, and any of yours): feeds `osg_ModelViewProjectionMatrix` to the current
/// program when the context's osg::State does not (OSG's uniform mode is off, as in stock
/// `osgviewer` and most applications with a compatibility context). volren's own contexts turn
/// the uniform mode on; then this callback only draws. The shaders read the vertex from
/// attribute 0, which is the fixed-function vertex array in a compatibility context.
class MatrixUniforms : public osg::Drawable::DrawCallback
{
public:
    void drawImplementation(osg::RenderInfo& renderInfo, const osg::Drawable* drawable) const override;
};

}  // namespace volren
