#version 330 core
// Overlay/annotation, fragment stage: each annotation shape in its one colour.
uniform vec4 volren_annotationColour;
out vec4 volren_fragColour;

void main()
{
    volren_fragColour = volren_annotationColour;
}
