// MultiVolume/sum_of_media: the RayTraversal of a multi-volume set, i.e. of volumes whose boxes
// overlap. One ray samples every member it passes through: where members overlap, their media
// add (optical depths add; emissions mix in proportion to optical depth), as in the CPU
// reference renderer. origin and dir are in the texture space of the set's box (the union of
// the members' boxes); each member's ray is the same line in its own texture space, with the
// same parameter t. Segments of volren_sampleDistance (the finest member step) tile the union
// of the members' intervals exactly; each member is sampled at the midpoint of the part of a
// segment inside its interval, so a homogeneous medium still gives exp(-sigma*L) at any step.
// Each member's Acceleration leaps over what it proves transparent in its own medium; the ray
// leaps where every member is empty, so the image is the one without skipping.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
// Calls, per member k (the compositor generates these dispatchers over MultiVolume/member.glsl):
void volren_setMemberRay(int k, vec3 origin, vec3 dir, out vec3 memberOrigin, out vec3 memberDir,
                         out float worldPerT, inout float tNear, inout float tFar);
float volren_setMemberSample(int k, vec3 pos, vec3 memberDir, float worldLength, out vec3 emitted);
float volren_setMemberSkip(int k, vec3 memberOrigin, vec3 memberDir, float t, float tFar, out float tRecheck);

// The first segment from which on member samples may be at or past t: one before the first whose
// midpoint is (a member's sample may lie up to half a step past the set's midpoint, where the
// member's interval starts inside a segment), at least i + 1.
int volren_setLeapTarget(VolrenMarch m, int i, float t)
{
    return max(i + 1, volren_segmentFrom(m, t) - 1);
}

vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    vec3 memberOrigin[VOLREN_MEMBER_COUNT];
    vec3 memberDir[VOLREN_MEMBER_COUNT];
    float worldPerT[VOLREN_MEMBER_COUNT];
    float enter[VOLREN_MEMBER_COUNT];
    float leave[VOLREN_MEMBER_COUNT];
    float first = tFar, last = tNear;
    for (int k = 0; k < VOLREN_MEMBER_COUNT; ++k) {
        enter[k] = tNear;
        leave[k] = tFar;
        volren_setMemberRay(k, origin, dir, memberOrigin[k], memberDir[k], worldPerT[k], enter[k], leave[k]);
        if (enter[k] < leave[k]) {
            first = min(first, enter[k]);
            last = max(last, leave[k]);
        }
    }
    VolrenMarch m;
    if (!(first < last) || !volren_beginMarch(dir, first, last, jitter, m)) return vec4(0.0);

    precise float depth = 0.0;
    precise float compensation = 0.0;
    vec3 color = vec3(0.0);
    // Empty-space skipping: each member's own answer, at its own sample of a segment; the ray
    // leaps to the first segment where some member's sample may be visible.
    float emptyUntil[VOLREN_MEMBER_COUNT];
    float recheck[VOLREN_MEMBER_COUNT];
    for (int k = 0; k < VOLREN_MEMBER_COUNT; ++k) {
        emptyUntil[k] = -1e30;
        recheck[k] = -1e30;
    }
    for (int i = 0; i < m.count;) {
        float segStart = volren_segmentStart(m, i, first, last);
        float segEnd = volren_segmentEnd(m, i, last);
        int leapTo = m.count;  // none of the members shows before this segment
        for (int k = 0; k < VOLREN_MEMBER_COUNT && leapTo > i; ++k) {
            if (!(leave[k] > segStart) || !(enter[k] < leave[k])) continue;  // behind the ray now, or never on it
            float a = max(segStart, enter[k]);
            float b = min(segEnd, leave[k]);
            if (!(b > a)) {  // ahead: empty until its interval starts
                leapTo = min(leapTo, volren_setLeapTarget(m, i, enter[k]));
                continue;
            }
            float t = 0.5 * (a + b);
            if (t >= recheck[k]) emptyUntil[k] = volren_setMemberSkip(k, memberOrigin[k], memberDir[k], t, leave[k], recheck[k]);
            leapTo = min(leapTo, emptyUntil[k] > t ? volren_setLeapTarget(m, i, emptyUntil[k]) : i);
        }
        if (leapTo > i) {
            i = leapTo;
            continue;
        }
        float dTau = 0.0;
        vec3 emission = vec3(0.0);  // sum of member optical depth x member colour
        for (int k = 0; k < VOLREN_MEMBER_COUNT; ++k) {
            float a = max(segStart, enter[k]);
            float b = min(segEnd, leave[k]);
            if (!(b > a)) continue;
            vec3 emitted;
            float memberTau = volren_setMemberSample(k, memberOrigin[k] + memberDir[k] * (0.5 * (a + b)), memberDir[k],
                                                     (b - a) * worldPerT[k], emitted);
            if (memberTau > 0.0) {
                dTau = min(dTau + memberTau, 1e30);
                emission += min(memberTau, 1e30) * emitted;
            }
        }
        if (dTau > 0.0) {
            color += exp(-depth) * volren_opacityFromDepth(dTau) * (emission / dTau);
            volren_addDepth(dTau, depth, compensation);
            if (depth >= volren_terminationDepth) break;
        }
        ++i;
    }
    return vec4(color, volren_opacityFromDepth(depth));
}
