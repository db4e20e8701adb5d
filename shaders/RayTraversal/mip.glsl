// RayTraversal/mip: MIP: the classified maximum of the reconstructed scalar along the ray (samples at the
// segment midpoints of the DVR traversal; clipped samples are ignored), premultiplied. The
// Acceleration leaps over cells whose values cannot pass the running maximum.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    float best = -3.4e38;
    bool found = false;
    float tRecheck = -1e30;
    for (int i = 0; i < m.count;) {
        int next = i + 1;
        float segStart = volren_segmentStart(m, i, tNear, tFar);
        float segEnd = volren_segmentEnd(m, i, tFar);
        float tMid = 0.5 * (segStart + segEnd);
        bool take = segEnd > segStart;
        // Skipping once a value is found (before, a sample of -inf still counts as found).
        if (take && found && tMid >= tRecheck) {
            float tNext = volren_skip(origin, dir, tMid, tFar, best, true, tRecheck);
            if (tNext >= tFar) break;
            if (tNext > tMid) {
                next = max(next, volren_segmentFrom(m, tNext));
                take = false;
            }
        }
        vec3 p = origin + dir * tMid;
        if (take && !volren_clipPosition(p)) {
            float s = volren_fetchScalar(p);
            if (s > best) best = s;  // NaN compares false and is skipped
            found = found || !isnan(s);
        }
        i = next;
    }
    if (!found) return vec4(0.0);
    vec4 c = volren_classify(best);
    return vec4(c.rgb * c.a, c.a);
}
