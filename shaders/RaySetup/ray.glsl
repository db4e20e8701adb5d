// RaySetup/ray.glsl (included by every ray setup): this pixel's ray and the common tail.
// The ray runs from this pixel's point on the near plane (t = 0) to its point on the far plane
// (t = 1), in volume texture space. Because it starts on the near plane, a camera inside the
// volume (or a near plane cutting the box) marches only what lies in front of the camera, for
// perspective and orthographic projections alike.
in vec4 volren_vClip;
in vec3 volren_vTexCoord;
flat in mat4 volren_clipToTexture;
flat in mat4 volren_textureToClip;
out vec4 volren_fragColor;

// This pixel's ray: origin on the near plane, origin + dir on the far plane.
void volren_pixelRay(out vec3 origin, out vec3 dir)
{
    vec2 ndc = volren_vClip.xy / volren_vClip.w;
    vec4 nearPoint = volren_clipToTexture * vec4(ndc, -1.0, 1.0);
    vec4 farPoint = volren_clipToTexture * vec4(ndc, 1.0, 1.0);
    origin = nearPoint.xyz / nearPoint.w;
    dir = farPoint.xyz / farPoint.w - origin;
}

// Where the ray is inside the box [0,1]^3 and between the near and far planes (slab test;
// zero direction components are nudged so the divisions stay finite).
void volren_boxInterval(vec3 origin, vec3 dir, out float tNear, out float tFar)
{
    vec3 safeDir = mix(dir, vec3(1e-30), equal(dir, vec3(0.0)));
    vec3 t0 = -origin / safeDir;
    vec3 t1 = (vec3(1.0) - origin) / safeDir;
    vec3 tMin = min(t0, t1);
    vec3 tMax = max(t0, t1);
    tNear = max(max(tMin.x, tMin.y), max(tMin.z, 0.0));
    tFar = min(min(tMax.x, tMax.y), min(tMax.z, 1.0));
}

// Ray parameter of a point p on the ray (a rasterised face point of this pixel).
float volren_rayParameter(vec3 origin, vec3 dir, vec3 p)
{
    return dot(p - origin, dir) / max(dot(dir, dir), 1e-30);
}

// Clips [tNear, tFar], marches it and writes the colour; a traversal that reports a surface
// (tHit >= 0) sets the fragment depth there. Discards rays with nothing left.
void volren_castRay(vec3 origin, vec3 dir, float tNear, float tFar)
{
    volren_clipRay(origin, dir, tNear, tFar);
    if (!(tNear < tFar)) discard;

    float tHit;
    vec4 color = volren_traverse(origin, dir, tNear, tFar, volren_jitter(gl_FragCoord.xy), tHit);
    if (any(isnan(color))) color = vec4(0.0);  // never let NaN reach the framebuffer
    if (volren_writesDepth) {
        if (tHit < 0.0) discard;  // no surface on this ray: leave colour and depth alone
        // Depth of the hit: the near-to-far parameter maps back through the projection.
        vec4 clip = volren_textureToClip * vec4(origin + dir * tHit, 1.0);
        gl_FragDepth = clamp(0.5 * (clip.z / clip.w) + 0.5, 0.0, 1.0);
    } else {
        gl_FragDepth = gl_FragCoord.z;
    }
    volren_fragColor = color;
#ifdef VOLREN_COUNT_SAMPLES
    volren_fragColor = vec4(float(volren_sampleCount), 0.0, 0.0, 1.0);  // the pass's debug output
#endif
}
