#version 430 core
// RaySetup/rasterised, entry pass: the box's front faces store their volume-space position
// (the rasterised colour cube) and this frame's stamp at their pixel, for the ray pass.
in vec3 volren_vTexCoord;
layout(rgba32f, binding = 0) uniform writeonly image2D volren_entryPoints;
uniform vec2 volren_viewportOrigin;
uniform float volren_frameStamp;

void main()
{
    imageStore(volren_entryPoints, ivec2(gl_FragCoord.xy - volren_viewportOrigin),
               vec4(volren_vTexCoord, volren_frameStamp));
}
