#version 430 core
// RaySetup vertex stage (every ray setup): draws the volume box (dims * spacing, centred on the
// node's origin; its corners are the proxy geometry's vertices) and hands the fragment stage
// its clip-space position, its volume-texture-space position (the rasterised "colour cube")
// and the clip <-> volume-texture-space matrices.
layout(location = 0) in vec4 osg_Vertex;  // location 0: also the fixed-function vertex array
uniform mat4 osg_ModelViewProjectionMatrix;
uniform vec3 volren_worldSize;
out vec4 volren_vClip;
out vec3 volren_vTexCoord;
flat out mat4 volren_clipToTexture;
flat out mat4 volren_textureToClip;

void main()
{
    mat4 textureToLocal = mat4(vec4(volren_worldSize.x, 0.0, 0.0, 0.0),
                               vec4(0.0, volren_worldSize.y, 0.0, 0.0),
                               vec4(0.0, 0.0, volren_worldSize.z, 0.0),
                               vec4(-0.5 * volren_worldSize, 1.0));
    mat4 textureToClip = osg_ModelViewProjectionMatrix * textureToLocal;
    volren_clipToTexture = inverse(textureToClip);
    volren_textureToClip = textureToClip;
    gl_Position = osg_ModelViewProjectionMatrix * osg_Vertex;
    volren_vClip = gl_Position;
    volren_vTexCoord = osg_Vertex.xyz / volren_worldSize + vec3(0.5);
}
