// RayTraversal/average: the classified length-weighted mean of the scalar along the
// unclipped part of the ray (an X-ray-like projection), premultiplied.
// vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit)
{
    tHit = -1.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return vec4(0.0);
    float sum = 0.0, weight = 0.0;
    for (int i = 0; i < m.count; ++i) {
        float segStart = volren_segmentStart(m, i, tNear, tFar);
        float segEnd = volren_segmentEnd(m, i, tFar);
        float lenT = segEnd - segStart;
        vec3 p = origin + dir * (0.5 * (segStart + segEnd));
        if (lenT > 0.0 && !volren_clipPosition(p)) {
            float s = volren_fetchScalar(p);
            if (!isnan(s)) {
                sum += s * lenT;
                weight += lenT;
            }
        }
    }
    if (!(weight > 0.0)) return vec4(0.0);
    vec4 c = volren_classify(sum / weight);
    return vec4(c.rgb * c.a, c.a);
}
