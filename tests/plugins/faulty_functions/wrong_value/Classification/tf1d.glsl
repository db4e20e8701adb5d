// Classification/tf1d, wrong on purpose (tests/plugins/faulty_functions): red and blue swapped,
// found first on $VOLREN_SHADER_PATH in place of the real file. It compiles, draws, repeats and
// agrees with its own variants (they swap too): only the reference sees it.
// vec4 volren_classify(float scalar)
vec4 volren_classify(float scalar)
{
    if (isnan(scalar)) return vec4(0.0);
    float u = clamp(scalar * volren_window.x * volren_window.z + volren_window.y, 0.0, 1.0);
    return texture(volren_transferFunction, (u * (volren_tfResolution - 1.0) + 0.5) / volren_tfResolution).bgra;
}
