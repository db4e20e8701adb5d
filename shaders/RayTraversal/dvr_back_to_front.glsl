// RayTraversal/dvr_back_to_front: the same segments and samples as front-to-back, composited
// from the far end (colour = c_i * a_i + (1 - a_i) * colour); no early termination possible.
// The Acceleration leaps (along the reversed ray) over samples it proves transparent and may
// let one sample stand for a run of steps (adaptive).
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    vec3 viewDir = -normalize(dir * volren_worldSize);

    precise float depth = 0.0;
    precise float compensation = 0.0;
    vec3 color = vec3(0.0);
    float tRecheck = 1e30;  // skipping runs along the reversed ray, parameter -t
    float tRunStart = 1e30;  // adaptive steps too: where their answer must be asked again
    int steps = 1;
    for (int i = m.count - 1; i >= 0;) {
        int next = i - 1;
        float segStart = volren_segmentStart(m, i, tNear, tFar);
        float segEnd = volren_segmentEnd(m, i, tFar);
        float lenT = segEnd - segStart;
        float tMid = 0.5 * (segStart + segEnd);
        bool visible = lenT > 0.0;
        if (visible && tMid <= tRecheck) {  // empty-space skipping: leap back to the next sample that may show
            float reversedRecheck;
            float tNext = -volren_skip(origin, -dir, -tMid, -tNear, reversedRecheck);
            tRecheck = -reversedRecheck;
            int at = volren_leapBack(m, i, tMid, tNext, tNear, tFar);
            visible = at == i;
            next = visible ? next : at;
        }
        if (visible) {  // adaptive sampling: one sample for a run of steps where the medium is homogeneous
            if (tMid <= tRunStart) {
                float reversedEnd;
                steps = volren_stepsPerSample(origin, -dir, -tMid, reversedEnd);
                tRunStart = -reversedEnd;
            }
            int first = steps > 1 ? max(max(i - steps, -1) + 1, volren_segmentStartingFrom(m, tRunStart)) : i;
            if (first < i) {
                segStart = volren_segmentStart(m, first, tNear, tFar);
                lenT = segEnd - segStart;
                tMid = 0.5 * (segStart + segEnd);
                next = first - 1;
            }
        }
        vec3 p = origin + dir * tMid;
        if (visible && !volren_clipPosition(p)) {
            vec4 c = volren_classify(volren_fetchScalar(p));
            c.a *= volren_weight(p);  // spatial weighting scales the sample's opacity
            float dTau = volren_opticalDepth(c.a, lenT * m.worldPerT / volren_referenceStep);
            if (dTau > 0.0) {
                float a = volren_opacityFromDepth(dTau);
                color = a * volren_shade(p, viewDir, c) + (1.0 - a) * color;
                volren_addDepth(dTau, depth, compensation);
            }
        }
        i = next;
    }
    return vec4(color, volren_opacityFromDepth(depth));
}
