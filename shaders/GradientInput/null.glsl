// GradientInput/null: a constant field (no gradient anywhere).
// float volren_gradientInput(vec3 pos)
float volren_gradientInput(vec3 pos)
{
    return 0.0;
}
