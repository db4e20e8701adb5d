#version 430 core
// Shadowing/light_volume on the opaque geometry, vertex stage: one triangle over the whole
// viewport (its vertices are NDC corners), drawn under the volume node's model-view so that the
// fragment stage can take each pixel back into the volume's texture space.
layout(location = 0) in vec4 osg_Vertex;  // location 0: also the fixed-function vertex array
uniform mat4 osg_ModelViewProjectionMatrix;
uniform vec3 volren_worldSize;
flat out mat4 volren_clipToTexture;

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
    volren_clipToTexture = volren_inverseScaled(osg_ModelViewProjectionMatrix * textureToLocal);
    gl_Position = vec4(osg_Vertex.xy, 0.0, 1.0);
}
