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

/// The inverse of `m`, its rows scaled to unit size first: the determinant of the unscaled
/// clip <-> texture matrix leaves float's range (above 3e38 for a perspective view of a box of
/// ~1e9 units, below 1e-38 for an orthographic view of ~1e13) and every ray turned NaN.
mat4 volren_inverseScaled(mat4 m)
{
    vec4 s = 1.0 / max(max(max(abs(m[0]), abs(m[1])), max(abs(m[2]), abs(m[3]))), vec4(1e-30));
    mat4 scaled = mat4(m[0] * s, m[1] * s, m[2] * s, m[3] * s);
    return inverse(scaled) * mat4(vec4(s.x, 0.0, 0.0, 0.0), vec4(0.0, s.y, 0.0, 0.0), vec4(0.0, 0.0, s.z, 0.0),
                                  vec4(0.0, 0.0, 0.0, s.w));
}

void main()
{
    mat4 textureToLocal = mat4(vec4(volren_worldSize.x, 0.0, 0.0, 0.0),
                               vec4(0.0, volren_worldSize.y, 0.0, 0.0),
                               vec4(0.0, 0.0, volren_worldSize.z, 0.0),
                               vec4(-0.5 * volren_worldSize, 1.0));
    mat4 textureToClip = osg_ModelViewProjectionMatrix * textureToLocal;
    volren_clipToTexture = volren_inverseScaled(textureToClip);
    volren_textureToClip = textureToClip;
    gl_Position = osg_ModelViewProjectionMatrix * osg_Vertex;
    volren_vClip = gl_Position;
    volren_vTexCoord = osg_Vertex.xyz / volren_worldSize + vec3(0.5);
}
