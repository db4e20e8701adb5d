// Weighting/axes: one piecewise-linear curve per axis of the volume's normalised coordinates
// (volume_model/SpatialWeighting.h), constant beyond its first and last knots; the weight is
// the product of the three. A curve through knots (u_i, w_i) is written as its first weight plus
// one hinge per segment: w(u) = w_0 + sum_i slope_i * clamp(u - u_i, 0, u_{i+1} - u_i). Axis a's
// segments 4g..4g+3 are element g of its vec4s (index 4a + g) of volren_weightStart (u_i),
// volren_weightLength (u_{i+1} - u_i) and volren_weightSlope; unused segments have length and
// slope 0; volren_weightBase[a] is w_0 (1 without knots). VOLREN_WEIGHT_GROUPS_X/Y/Z (its compile
// options) say how many vec4s of each axis hold segments: only those are evaluated.
// No loops, and no branches or indexing on a sample's value: a fragment's loop iterations are limited
// in total on some drivers (llvmpipe stops every loop after 65535), drivers that run both sides
// of a branch under a mask pay for both, and a sample's weight is asked inside the march and its
// shadow rays.
// float volren_weight(vec3 pos)

// Group g (0..3) of axis a's hinges at coordinate u.
float volren_weightHinges(int a, int g, float u)
{
    int i = 4 * a + g;
    return dot(clamp(vec4(u) - volren_weightStart[i], vec4(0.0), volren_weightLength[i]), volren_weightSlope[i]);
}

float volren_axisWeight(int axis, float u, int groups)
{
    float w = volren_weightBase[axis];
    if (groups > 0) w += volren_weightHinges(axis, 0, u);
    if (groups > 1) w += volren_weightHinges(axis, 1, u);
    if (groups > 2) w += volren_weightHinges(axis, 2, u);
    if (groups > 3) w += volren_weightHinges(axis, 3, u);
    return w;
}

float volren_weight(vec3 pos)
{
    // groups are constants: the compiler keeps only the hinges the curves have
    return clamp(volren_axisWeight(0, pos.x, VOLREN_WEIGHT_GROUPS_X) * volren_axisWeight(1, pos.y, VOLREN_WEIGHT_GROUPS_Y) *
                     volren_axisWeight(2, pos.z, VOLREN_WEIGHT_GROUPS_Z),
                 0.0, 1.0);
}
