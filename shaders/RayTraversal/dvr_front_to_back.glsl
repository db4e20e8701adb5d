// RayTraversal/dvr_front_to_back: emission-absorption compositing, front to back, with early
// termination once the accumulated opacity reaches the threshold; the Acceleration leaps over
// samples it proves transparent and may let one sample stand for a run of steps (adaptive).
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
// Segments (march.glsl) tile [tNear, tFar] exactly and are sampled at their midpoints, so a
// homogeneous medium gives exp(-sigma*L) at any step.
// Optical depth is summed with Kahan compensation; transmittance is exp(-depth).
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    vec3 viewDir = -normalize(dir * volren_worldSize);

    precise float depth = 0.0;
    precise float compensation = 0.0;
    vec3 color = vec3(0.0);
    float tRecheck = -1e30;
    float tRunEnd = -1e30;  // where the Acceleration's answer on adaptive steps must be asked again
    int steps = 1;
    for (int i = 0; i < m.count;) {
        int next = i + 1;
        float segStart = volren_segmentStart(m, i, tNear, tFar);
        float segEnd = volren_segmentEnd(m, i, tFar);
        float lenT = segEnd - segStart;
        float tMid = 0.5 * (segStart + segEnd);
        bool visible = lenT > 0.0;
        if (visible && tMid >= tRecheck) {  // empty-space skipping: leap to the next sample that may show
            int at = volren_leap(m, i, tMid, volren_skip(origin, dir, tMid, tFar, tRecheck), tNear, tFar);
            visible = at == i;
            next = visible ? next : at;
        }
        if (visible) {  // adaptive sampling: one sample for a run of steps where the medium is homogeneous
            if (tMid >= tRunEnd) steps = volren_stepsPerSample(origin, dir, tMid, tRunEnd);
            int last = steps > 1 ? min(min(i + steps, m.count) - 1, volren_segmentEndingBy(m, tRunEnd)) : i;
            if (last > i) {
                segEnd = volren_segmentEnd(m, last, tFar);
                lenT = segEnd - segStart;
                tMid = 0.5 * (segStart + segEnd);
                next = last + 1;
            }
        }
        vec3 p = origin + dir * tMid;
        if (visible && !volren_clipPosition(p)) {
            vec4 c = volren_classify(volren_fetchScalar(p));
            c.a *= volren_weight(p);  // spatial weighting scales the sample's opacity
            float dTau = volren_opticalDepth(c.a, lenT * m.worldPerT / volren_referenceStep);
            if (dTau > 0.0) {
                color += exp(-depth) * volren_opacityFromDepth(dTau) * volren_shade(p, viewDir, c);
                volren_addDepth(dTau, depth, compensation);
                if (depth >= volren_terminationDepth) break;
            }
        }
        i = next;
    }
    return vec4(color, volren_opacityFromDepth(depth));
}
