// Reconstruction/tricubic: cubic B-spline reconstruction from 8 trilinear fetches
// (Sigg & Hadwiger, GPU Gems 2 ch. 20). It reproduces linear fields exactly and smooths noise.
// volren_dims are the voxels of the volume texture (the mip level the node samples).
// float volren_fetchScalar(vec3 pos)
float volren_fetchScalar(vec3 pos)
{
#ifdef VOLREN_COUNT_SAMPLES
    ++volren_sampleCount;
#endif
    vec3 x = pos * volren_dims - 0.5;
    vec3 index = floor(x);
    vec3 f = x - index;
    vec3 f2 = f * f, f3 = f2 * f, one = 1.0 - f;
    // Cubic B-spline weights of the four neighbours.
    vec3 w0 = one * one * one / 6.0;
    vec3 w1 = (4.0 - 6.0 * f2 + 3.0 * f3) / 6.0;
    vec3 w3 = f3 / 6.0;
    vec3 w2 = 1.0 - w0 - w1 - w3;
    // Two linear fetches per axis replace four nearest ones.
    vec3 g0 = w0 + w1, g1 = w2 + w3;
    vec3 h0 = (index - 0.5 + w1 / g0) / volren_dims;  // texel centres are at (i + 0.5) / n
    vec3 h1 = (index + 1.5 + w3 / g1) / volren_dims;
    float v000 = volren_volumeSample(vec3(h0.x, h0.y, h0.z));
    float v100 = volren_volumeSample(vec3(h1.x, h0.y, h0.z));
    float v010 = volren_volumeSample(vec3(h0.x, h1.y, h0.z));
    float v110 = volren_volumeSample(vec3(h1.x, h1.y, h0.z));
    float v001 = volren_volumeSample(vec3(h0.x, h0.y, h1.z));
    float v101 = volren_volumeSample(vec3(h1.x, h0.y, h1.z));
    float v011 = volren_volumeSample(vec3(h0.x, h1.y, h1.z));
    float v111 = volren_volumeSample(vec3(h1.x, h1.y, h1.z));
    float y0 = g0.x * (g0.y * v000 + g1.y * v010) + g1.x * (g0.y * v100 + g1.y * v110);
    float y1 = g0.x * (g0.y * v001 + g1.y * v011) + g1.x * (g0.y * v101 + g1.y * v111);
    return g0.z * y0 + g1.z * y1;
}
