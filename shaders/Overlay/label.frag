#version 330 core
// Overlay/label, fragment stage: the label's colour where its glyphs cover the pixel (the
// image's coverage), blended over what is drawn.
uniform sampler2D volren_labelTexture;
uniform vec4 volren_annotationColour;
in vec2 volren_labelCoordinate;
out vec4 volren_fragColour;

void main()
{
    float coverage = texture(volren_labelTexture, volren_labelCoordinate).r;
    volren_fragColour = vec4(volren_annotationColour.rgb, volren_annotationColour.a * coverage);
}
