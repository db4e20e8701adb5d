// MultiVolume/additive: a RayTraversal of a multi-volume set (channels of a microscopy volume,
// overlapping volumes) that adds the members' images instead of their media: each member is
// marched on its own, front to back through its own emission and absorption (its segments of
// volren_sampleDistance tile its own interval of the ray, its own skipping and early
// termination), so no member occludes another (napari's additive blending); the images add in
// MultiVolume/add_images.glsl (volren_traverse).
// vec4 volren_memberImage(int k, vec3 dir, vec3 memberOrigin, vec3 memberDir, float worldPerT, float tNear,
//                         float tFar, float jitter)
// Calls, per member k (the compositor generates these dispatchers over MultiVolume/member.glsl):
float volren_setMemberSample(int k, vec3 pos, vec3 memberDir, float worldLength, out vec3 emitted);
float volren_setMemberSkip(int k, vec3 memberOrigin, vec3 memberDir, float t, float tFar, out float tRecheck);

vec4 volren_memberImage(int k, vec3 dir, vec3 memberOrigin, vec3 memberDir, float worldPerT, float tNear, float tFar,
                        float jitter)
{
    VolrenMarch m;
    if (!(tNear < tFar) || !volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    precise float depth = 0.0;
    precise float compensation = 0.0;
    vec3 color = vec3(0.0);
    float tRecheck = -1e30;
    for (int i = 0; i < m.count;) {
        float segStart = volren_segmentStart(m, i, tNear, tFar);
        float segEnd = volren_segmentEnd(m, i, tFar);
        float tMid = 0.5 * (segStart + segEnd);
        if (tMid >= tRecheck) {
            int at = volren_leap(m, i, tMid, volren_setMemberSkip(k, memberOrigin, memberDir, tMid, tFar, tRecheck),
                                 tNear, tFar);
            if (at != i) {
                i = at;
                continue;
            }
        }
        vec3 emitted;
        float dTau = volren_setMemberSample(k, memberOrigin + memberDir * tMid, memberDir, (segEnd - segStart) * worldPerT,
                                            emitted);
        if (dTau > 0.0) {
            color += exp(-depth) * volren_opacityFromDepth(dTau) * emitted;
            volren_addDepth(dTau, depth, compensation);
            if (depth >= volren_terminationDepth) break;
        }
        ++i;
    }
    return vec4(color, volren_opacityFromDepth(depth));
}
