#version 330 core
// Overlay/label, vertex stage: a text label of the screen annotations (Annotations.h), a quad in
// viewport pixels over the label's image (glyphs of a font composed on the CPU); its texture
// coordinate follows from the position, so no array but the vertices is needed.
layout(location = 0) in vec4 osg_Vertex;  // location 0: also the fixed-function vertex array
uniform mat4 osg_ModelViewProjectionMatrix;
uniform vec2 volren_labelOrigin;  // the image's lower left corner, pixels
uniform vec2 volren_labelSize;    // the image's size, pixels
out vec2 volren_labelCoordinate;

void main()
{
    volren_labelCoordinate = (osg_Vertex.xy - volren_labelOrigin) / volren_labelSize;
    gl_Position = osg_ModelViewProjectionMatrix * osg_Vertex;
}
