// MultiVolume/add_images.glsl (included by the set traversals that add their members' images:
// additive, mip_additive): each member's image of its own interval of the set's ray
// (volren_memberImage, defined by the including traversal), premultiplied, the colours added and
// clamped to 1, the coverage 1 - prod(1 - alpha_k).
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
void volren_setMemberRay(int k, vec3 origin, vec3 dir, out vec3 memberOrigin, out vec3 memberDir,
                         out float worldPerT, inout float tNear, inout float tFar);
vec4 volren_memberImage(int k, vec3 dir, vec3 memberOrigin, vec3 memberDir, float worldPerT, float tNear, float tFar,
                        float jitter);

vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    vec3 color = vec3(0.0);
    float clear = 1.0;  // prod(1 - alpha_k)
    for (int k = 0; k < VOLREN_MEMBER_COUNT; ++k) {
        vec3 memberOrigin, memberDir;
        float worldPerT;
        float enter = tNear, leave = tFar;
        volren_setMemberRay(k, origin, dir, memberOrigin, memberDir, worldPerT, enter, leave);
        vec4 image = volren_memberImage(k, dir, memberOrigin, memberDir, worldPerT, enter, leave, jitter);
        color += image.rgb;
        clear *= 1.0 - image.a;
    }
    return vec4(min(color, vec3(1.0)), 1.0 - clear);
}
