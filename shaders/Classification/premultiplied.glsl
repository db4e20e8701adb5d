// Classification/premultiplied: the table holds associated colours (rgb * alpha, alpha), so
// interpolating between entries does not bleed the colour of transparent entries into
// opaque ones; the result is returned unassociated again.
// vec4 volren_classify(float scalar)
vec4 volren_classify(float scalar)
{
    if (isnan(scalar)) return vec4(0.0);
    float u = clamp(scalar * volren_window.x * volren_window.z + volren_window.y, 0.0, 1.0);
    vec4 c = texture(volren_premultipliedTable, (u * (volren_tfResolution - 1.0) + 0.5) / volren_tfResolution);
    return c.a > 0.0 ? vec4(c.rgb / c.a, c.a) : vec4(0.0);
}
