// common/numerics.glsl: accurate log1p/expm1 and opacity correction, shared by all slots.
// GLSL has no log1p/expm1, and GPU log/exp are only accurate in absolute terms near 1 (Mesa's
// llvmpipe loses ~10% relative accuracy for exp(x)-1 at x ~ 1e-7). Small arguments therefore
// use their series, which need no library accuracy: degree 8 on |x| <= 1/8 keeps the relative
// error below 1e-9; larger arguments are far enough from 1 for log/exp themselves.

#ifdef VOLREN_COUNT_SAMPLES
// The pass's debug output of sample counts: every Reconstruction call of this invocation, one
// counter for all members of a multi-volume set (RaySetup/ray.glsl writes it out).
int volren_sampleCount = 0;
#endif

float volren_log1p(float x)
{
    if (abs(x) > 0.125) return log(1.0 + x);
    // x - x^2/2 + x^3/3 - ... - x^8/8, Horner form
    return x * (1.0 + x * (-1.0 / 2.0 + x * (1.0 / 3.0 + x * (-1.0 / 4.0 + x * (1.0 / 5.0 +
           x * (-1.0 / 6.0 + x * (1.0 / 7.0 + x * (-1.0 / 8.0))))))));
}

float volren_expm1(float x)
{
    if (abs(x) > 0.125) return exp(x) - 1.0;
    // x + x^2/2! + ... + x^8/8!, Horner form
    return x * (1.0 + x * (1.0 / 2.0 + x * (1.0 / 6.0 + x * (1.0 / 24.0 + x * (1.0 / 120.0 +
           x * (1.0 / 720.0 + x * (1.0 / 5040.0 + x * (1.0 / 40320.0))))))));
}

// Optical depth of a segment `ratio` reference segments long, whose reference opacity is alpha:
// -ratio * log(1 - alpha). Opaque (alpha >= 1) gives a large finite depth, never Inf or NaN.
float volren_opticalDepth(float alpha, float ratio)
{
    if (!(alpha > 0.0) || !(ratio > 0.0)) return 0.0;
    if (alpha >= 1.0) return 1e30;
    return min(-volren_log1p(-alpha) * ratio, 1e30);
}

// Opacity of a segment of optical depth tau: 1 - exp(-tau), accurate for tiny tau.
float volren_opacityFromDepth(float tau)
{
    return -volren_expm1(-tau);
}

// Unit normal from a gradient, facing the viewer (two-sided lighting). A zero, tiny, huge or
// NaN gradient gives the view direction, as in the CPU reference: a sample's colour depends on
// its position and the view only, never on the samples before it along the ray.
vec3 volren_normalFromGradient(vec3 gradient, vec3 viewDir)
{
    float scale = max(max(abs(gradient.x), abs(gradient.y)), abs(gradient.z));
    // (max() may pass over a NaN component: a NaN voxel among the gradient's taps.)
    if (any(isnan(gradient)) || !(scale > 1e-30) || isinf(scale)) return viewDir;
    vec3 n = -normalize(gradient / scale);  // normals point from dense to empty
    return dot(n, viewDir) < 0.0 ? -n : n;
}

// How far pos (inside the unit box of texture space) goes along dir (texture space per unit of
// the caller's length) before leaving the box, in those units; 1e30 for a zero direction.
float volren_boxExit(vec3 pos, vec3 dir)
{
    float exitDistance = 1e30;
    for (int a = 0; a < 3; ++a) {
        if (dir[a] > 1e-30) exitDistance = min(exitDistance, (1.0 - pos[a]) / dir[a]);
        else if (dir[a] < -1e-30) exitDistance = min(exitDistance, -pos[a] / dir[a]);
    }
    return exitDistance;
}
