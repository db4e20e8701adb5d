// Classification/threshold: opaque where the windowed scalar reaches volren_threshold (in
// the TF's colour there), empty elsewhere.
// vec4 volren_classify(float scalar)
vec4 volren_classify(float scalar)
{
    if (isnan(scalar)) return vec4(0.0);
    float u = clamp(scalar * volren_window.x * volren_window.z + volren_window.y, 0.0, 1.0);
    if (u < volren_threshold) return vec4(0.0);
    vec4 c = texture(volren_transferFunction, (u * (volren_tfResolution - 1.0) + 0.5) / volren_tfResolution);
    return vec4(c.rgb, 1.0);
}
