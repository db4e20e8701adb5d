// Classification/null: no transfer function; the windowed scalar u in [0,1] is grey emission
// with opacity u.
// vec4 volren_classify(float scalar)
vec4 volren_classify(float scalar)
{
    if (isnan(scalar)) return vec4(0.0);
    float u = clamp(scalar * volren_window.x * volren_window.z + volren_window.y, 0.0, 1.0);
    return vec4(u, u, u, u);
}
