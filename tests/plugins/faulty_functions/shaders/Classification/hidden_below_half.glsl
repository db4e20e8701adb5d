// Classification/hidden_below_half (a probe, tests/plugins/faulty_functions): a grey ramp of the
// raw scalar, while its CPU mirror calls values below 0.5 invisible (FaultyFunctions.cpp).
// vec4 volren_classify(float scalar)
vec4 volren_classify(float scalar)
{
    if (isnan(scalar)) return vec4(0.0);
    float u = clamp(scalar, 0.0, 1.0);
    return vec4(u, u, u, 0.5 * u);
}
