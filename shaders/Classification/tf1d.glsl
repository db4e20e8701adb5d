// Classification/tf1d: post-classification through the 1D transfer-function table.
// vec4 volren_classify(float scalar)
// volren_window maps the texel value onto the TF's value window [0,1]; the table holds
// volren_tfResolution entries with entry 0 at window 0 and the last at window 1.
vec4 volren_classify(float scalar)
{
    if (isnan(scalar)) return vec4(0.0);
    float u = clamp(scalar * volren_window.x * volren_window.z + volren_window.y, 0.0, 1.0);
    return texture(volren_transferFunction, (u * (volren_tfResolution - 1.0) + 0.5) / volren_tfResolution);
}
