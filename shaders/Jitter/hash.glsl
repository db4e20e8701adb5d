// Jitter/hash: per-pixel offset from an integer hash of the pixel position (no texture).
// Deterministic: the same pixel gets the same offset every frame.
// float volren_jitter(vec2 fragCoord)
float volren_jitter(vec2 fragCoord)
{
    uvec2 p = uvec2(fragCoord);
    uint h = p.x * 1664525u + p.y * 1013904223u + 0x9e3779b9u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h >> 8) * (1.0 / 16777216.0);
}
