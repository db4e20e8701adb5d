// RayTraversal/isosurface: the first place where the scalar rises to the iso value,
// refined by bisection, shaded as an opaque surface in the TF's colour at the iso value;
// reports its ray parameter so the surface writes depth.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    float stepT = m.stepT;
    vec3 viewDir = -normalize(dir * volren_worldSize);
    float iso = volren_isoTexel;
    float tPrev = tNear;
    float prev = volren_clipPosition(origin + dir * tNear) ? -3.4e38 : volren_fetchScalar(origin + dir * tNear);
    if (prev >= iso) {  // the ray starts inside the surface (camera or clip plane in the object)
        tHit = tNear;
    } else {
        int count = int(ceil(max(tFar - tNear, 0.0) / stepT)) + 1;
        for (int i = 1; i <= count && tHit < 0.0; ++i) {
            float t = min(tNear + (float(i) - jitter) * stepT, tFar);
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
            if (t >= tFar) break;
        }
    }
    if (tHit < 0.0) return vec4(0.0);
    vec3 p = origin + dir * tHit;
    vec4 c = volren_classify(iso);
    return vec4(volren_shade(p, viewDir, vec4(c.rgb, 1.0)), 1.0);
}
