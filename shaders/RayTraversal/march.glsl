// RayTraversal/march.glsl (included by the marching traversals): segments of one sample
// distance that tile [tNear, tFar] exactly, the first shortened by the jitter and the last
// by the exit; each is sampled at its midpoint.
struct VolrenMarch
{
    float worldPerT;  // world length of one unit of t
    float stepT;      // sample distance in t
    float firstEnd;   // end of the first segment
    int count;        // number of segments
};

// Sets up the segments of [tNear, tFar]; false when the ray has no length.
bool volren_beginMarch(vec3 dir, float tNear, float tFar, float jitter, out VolrenMarch m)
{
    m.worldPerT = length(dir * volren_worldSize);
    m.stepT = volren_sampleDistance / max(m.worldPerT, 1e-30);
    m.firstEnd = tNear + (1.0 - jitter) * m.stepT;
    m.count = int(ceil(max(tFar - m.firstEnd, 0.0) / m.stepT)) + 1;
    return m.worldPerT > 0.0;
}

// End of segment i; the last one ends exactly at tFar.
float volren_segmentEnd(VolrenMarch m, int i, float tFar)
{
    return i == m.count - 1 ? tFar : min(m.firstEnd + float(i) * m.stepT, tFar);
}

// Start of segment i.
float volren_segmentStart(VolrenMarch m, int i, float tNear, float tFar)
{
    return i == 0 ? tNear : volren_segmentEnd(m, i - 1, tFar);
}

// Empty-space skipping's leaps: the first segment whose midpoint is at or after t, and the last
// whose midpoint is at or before it (both clamped to [-1, count]).
int volren_segmentFrom(VolrenMarch m, float t)
{
    return int(clamp(ceil((t - m.firstEnd) / m.stepT + 0.5), -1.0, float(m.count)));
}
int volren_segmentUpTo(VolrenMarch m, float t)
{
    return int(clamp(floor((t - m.firstEnd) / m.stepT + 0.5), -1.0, float(m.count)));
}

// Adaptive steps' runs: the last segment that ends at or before t, and the first that starts at
// or after it (clamped to [-1, count - 1] and [0, count]).
int volren_segmentEndingBy(VolrenMarch m, float t)
{
    return int(clamp(floor((t - m.firstEnd) / m.stepT), -1.0, float(m.count - 1)));
}
int volren_segmentStartingFrom(VolrenMarch m, float t)
{
    return int(clamp(ceil((t - m.firstEnd) / m.stepT) + 1.0, 0.0, float(m.count)));
}

// The midpoint of segment i, computed as the march computes it.
float volren_segmentMid(VolrenMarch m, int i, float tNear, float tFar)
{
    return 0.5 * (volren_segmentStart(m, i, tNear, tFar) + volren_segmentEnd(m, i, tFar));
}

// Where a march goes on after volren_skip answered tNext for the sample of segment i at tMid:
// i itself when that sample may show, else the first segment whose midpoint is at or past tNext
// (count, or -1 marching backwards, when nothing before the ray's end may show). The index from
// the division is checked against the midpoint the march itself computes, so float rounding
// never leaps over a sample just past tNext (one the skipping proved nothing about).
int volren_leap(VolrenMarch m, int i, float tMid, float tNext, float tNear, float tFar)
{
    if (tNext >= tFar) return m.count;
    if (!(tNext > tMid)) return i;
    int j = max(i + 1, volren_segmentFrom(m, tNext));
    if (j - 1 > i && volren_segmentMid(m, j - 1, tNear, tFar) >= tNext) --j;
    return j;
}
int volren_leapBack(VolrenMarch m, int i, float tMid, float tNext, float tNear, float tFar)
{
    if (tNext <= tNear) return -1;
    if (!(tNext < tMid)) return i;
    int j = min(i - 1, volren_segmentUpTo(m, tNext));
    if (j + 1 < i && volren_segmentMid(m, j + 1, tNear, tFar) <= tNext) ++j;
    return j;
}

// Adds a segment's optical depth dTau to depth, Kahan-compensated (tiny depths stay exact
// along rays of millions of samples).
void volren_addDepth(float dTau, inout float depth, inout float compensation)
{
    precise float y = dTau - compensation;
    precise float t = depth + y;
    compensation = (t - depth) - y;
    depth = t;
}
