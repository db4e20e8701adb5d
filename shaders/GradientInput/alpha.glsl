// GradientInput/alpha: gradients of the classified opacity (surfaces where the TF puts them).
// float volren_gradientInput(vec3 pos)
float volren_gradientInput(vec3 pos)
{
    return volren_classify(volren_fetchScalar(pos)).a;
}
