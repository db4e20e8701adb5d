// RayTraversal/extremum.glsl (included by mip and minip): the largest (maximum) or smallest
// reconstructed scalar along the ray, sampled at the segment midpoints of the DVR traversal;
// clipped and NaN samples and samples of weight 0 (Weighting) are ignored, found tells whether any
// sample counted and weight is the Weighting's factor where the extremum was found (the largest
// where several samples reach it). Once a value is
// found (before, a sample of -inf or +inf still counts as found) the Acceleration leaps over
// cells whose values cannot reach past it.
float volren_extremum(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, bool maximum, out bool found,
                      out float weight)
{
    float best = maximum ? -3.4e38 : 3.4e38;
    found = false;
    weight = 0.0;
    VolrenMarch m;
    if (!volren_beginMarch(dir, tNear, tFar, jitter, m)) return best;
    float tRecheck = -1e30;
    for (int i = 0; i < m.count;) {
        int next = i + 1;
        float segStart = volren_segmentStart(m, i, tNear, tFar);
        float segEnd = volren_segmentEnd(m, i, tFar);
        float tMid = 0.5 * (segStart + segEnd);
        bool take = segEnd > segStart;
        if (take && found && tMid >= tRecheck) {
            int at = volren_leap(m, i, tMid, volren_skip(origin, dir, tMid, tFar, best, maximum, tRecheck), tNear, tFar);
            take = at == i;
            next = take ? next : at;
        }
        vec3 p = origin + dir * tMid;
        float w = take && !volren_clipPosition(p) ? volren_weight(p) : 0.0;
        if (w > 0.0) {
            float s = volren_fetchScalar(p);
            if (maximum ? s > best : s < best) {  // NaN compares false and is skipped
                best = s;
                weight = w;
            } else if (s == best && w > weight) {  // a tie shows as its most weighted sample
                weight = w;
            }
            if (!found && !isnan(s)) {  // the first value, infinite or not, counts
                found = true;
                if (weight == 0.0) weight = w;
            }
        }
        i = next;
    }
    return best;
}
