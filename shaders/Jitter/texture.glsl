// Jitter/texture: per-pixel offset read from a 64x64 tile of uniform random numbers.
// float volren_jitter(vec2 fragCoord)
float volren_jitter(vec2 fragCoord)
{
    return texelFetch(volren_jitterTexture, ivec2(fragCoord) & 63, 0).r;
}
