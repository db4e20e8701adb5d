// GradientInput/scalar: gradients of the reconstructed scalar.
// float volren_gradientInput(vec3 pos)
float volren_gradientInput(vec3 pos)
{
    return volren_fetchScalar(pos);
}
