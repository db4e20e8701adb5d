// ClipRay/depth: ends the ray at the opaque geometry drawn before the volumes. The pass copies
// that geometry's depth buffer into volren_depthTexture; the depth at this pixel is projected
// back onto the ray, so nothing behind the geometry is marched and what lies in front of it
// attenuates it by the right amount. Template instance (one per scene with opaque geometry).
// void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar)
void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar)
{
    float depth = texelFetch(volren_depthTexture, ivec2(gl_FragCoord.xy - volren_viewportOrigin), 0).r;
    if (depth >= 1.0) return;  // no geometry at this pixel
    // Clip-space point of ray parameter t: a + t * b. Its NDC depth z(t) = (a.z + t b.z) / (a.w + t b.w)
    // equals the stored depth's NDC value at t = (a.z - z a.w) / (z b.w - b.z).
    mat4 textureToLocal = mat4(vec4(volren_worldSize.x, 0.0, 0.0, 0.0),
                               vec4(0.0, volren_worldSize.y, 0.0, 0.0),
                               vec4(0.0, 0.0, volren_worldSize.z, 0.0),
                               vec4(-0.5 * volren_worldSize, 1.0));
    mat4 textureToClip = osg_ModelViewProjectionMatrix * textureToLocal;
    vec4 a = textureToClip * vec4(origin, 1.0);
    vec4 b = textureToClip * vec4(dir, 0.0);
    float z = 2.0 * depth - 1.0;
    float denominator = z * b.w - b.z;
    if (denominator == 0.0) return;
    tFar = min(tFar, (a.z - z * a.w) / denominator);
}
