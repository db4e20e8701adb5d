// common/numerics.glsl: accurate log1p/expm1 and opacity correction, shared by all slots.
// GLSL has no log1p/expm1; these use the classic compensation forms, exact to a few ulp for
// tiny arguments where log(1+x) and exp(x)-1 would lose every digit.

float volren_log1p(float x)
{
    precise float u = 1.0 + x;
    if (u == 1.0) return x;
    precise float um1 = u - 1.0;
    return log(u) * (x / um1);
}

float volren_expm1(float x)
{
    if (abs(x) > 0.5) return exp(x) - 1.0;
    precise float u = exp(x);
    if (u == 1.0) return x;
    precise float um1 = u - 1.0;
    return um1 * (x / log(u));
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
