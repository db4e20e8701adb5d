// Classification/tf1d: post-classification through the 1D transfer-function table.
// vec4 volren_classify(float scalar)
// volren_tfScaleOffset maps the texel value to the table coordinate (value window and
// texel-centre mapping folded in on the CPU).
vec4 volren_classify(float scalar)
{
    if (isnan(scalar)) return vec4(0.0);
    float u = clamp(scalar * volren_tfScaleOffset.x + volren_tfScaleOffset.y, 0.0, 1.0);
    return texture(volren_transferFunction, u);
}
