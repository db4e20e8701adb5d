// RayTraversal/isosurface: the first place where the scalar rises to the iso value,
// refined by bisection, shaded as an opaque surface in the TF's colour at the iso value;
// reports its ray parameter so the surface writes depth. The Acceleration leaps over cells
// whose values stay below the iso value, landing on the sample the full march would reach.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)

// The largest float below x (for "stays below": a sample equal to the iso value is a hit); below
// the normal range, the largest negative normal float, which no flush of denormals moves up.
float volren_below(float x)
{
    if (isnan(x) || isinf(x)) return x;
    if (abs(x) < 1.17549435e-38) return -1.17549435e-38;
    uint bits = floatBitsToUint(x);
    return uintBitsToFloat(x > 0.0 ? bits - 1u : bits + 1u);
}

// Sample k >= 1 of the march (sample 0 is at tNear).
float volren_isoSample(int k, float tNear, float tFar, float stepT, float jitter)
{
    return min(tNear + (float(k) - jitter) * stepT, tFar);
}

vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    float stepT = m.stepT;
    vec3 viewDir = -normalize(dir * volren_worldSize);
    float iso = volren_isoTexel;
    float below = volren_below(iso);
    float tPrev = tNear;
    float prev = volren_clipPosition(origin + dir * tNear) ? -3.4e38 : volren_fetchScalar(origin + dir * tNear);
    if (prev >= iso) {  // the ray starts inside the surface (camera or clip plane in the object)
        tHit = tNear;
    } else {
        int count = int(ceil(max(tFar - tNear, 0.0) / stepT)) + 1;
        float tRecheck = -1e30;
        for (int i = 1; i <= count && tHit < 0.0;) {
            int next = i + 1;
            float t = volren_isoSample(i, tNear, tFar, stepT, jitter);
            bool take = true;
            if (t >= tRecheck) {  // leap over cells whose values stay below the iso value
                float tNext = volren_skip(origin, dir, t, tFar, below, true, tRecheck);
                if (tNext > tFar) break;
                if (tNext > t) {
                    // The first sample at or past tNext, checked against the samples as computed
                    // (a rounded division must not leap one just past tNext); the one before it,
                    // below the iso value, is the bisection's other end.
                    int j = max(next, int(ceil((tNext - tNear) / stepT + jitter)));
                    if (j - 1 > i && volren_isoSample(j - 1, tNear, tFar, stepT, jitter) >= tNext) --j;
                    next = j;
                    tPrev = volren_isoSample(next - 1, tNear, tFar, stepT, jitter);
                    take = false;
                }
            }
            if (take) {
                vec3 p = origin + dir * t;
                float s = volren_clipPosition(p) ? -3.4e38 : volren_fetchScalar(p);
                if (s >= iso) {
                    // Bisection between the last sample below and this one above the iso value.
                    float lo = tPrev, hi = t;
                    for (int k = 0; k < 12; ++k) {
                        float mid = 0.5 * (lo + hi);
                        vec3 q = origin + dir * mid;
                        float v = volren_clipPosition(q) ? -3.4e38 : volren_fetchScalar(q);
                        if (v >= iso) hi = mid;
                        else lo = mid;
                    }
                    tHit = hi;
                }
                tPrev = t;
            }
            if (t >= tFar) break;
            i = next;
        }
    }
    if (tHit < 0.0) return vec4(0.0);
    vec3 p = origin + dir * tHit;
    vec4 c = volren_classify(iso);
    return vec4(volren_shade(p, viewDir, vec4(c.rgb, 1.0)), 1.0);
}
