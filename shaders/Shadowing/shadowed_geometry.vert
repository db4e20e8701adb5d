#version 430 core
// Shadowing/light_volume on the opaque geometry, vertex stage: one triangle over the whole
// viewport (its vertices are NDC corners), drawn under the volume node's model-view so that the
// fragment stage can take each pixel back into the volume's texture space.
layout(location = 0) in vec4 osg_Vertex;  // location 0: also the fixed-function vertex array
uniform mat4 osg_ModelViewProjectionMatrix;
uniform vec3 volren_worldSize;
flat out mat4 volren_clipToTexture;

void main()
{
    mat4 textureToLocal = mat4(vec4(volren_worldSize.x, 0.0, 0.0, 0.0),
                               vec4(0.0, volren_worldSize.y, 0.0, 0.0),
                               vec4(0.0, 0.0, volren_worldSize.z, 0.0),
                               vec4(-0.5 * volren_worldSize, 1.0));
    volren_clipToTexture = inverse(osg_ModelViewProjectionMatrix * textureToLocal);
    gl_Position = vec4(osg_Vertex.xy, 0.0, 1.0);
}
