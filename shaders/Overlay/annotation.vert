#version 330 core
// Overlay/annotation, vertex stage: the screen annotations (scale bar, axis gizmo; Annotations.h)
// in pixels of the viewport, under the HUD camera's projection.
layout(location = 0) in vec4 osg_Vertex;  // location 0: also the fixed-function vertex array
uniform mat4 osg_ModelViewProjectionMatrix;

void main()
{
    gl_Position = osg_ModelViewProjectionMatrix * osg_Vertex;
}
