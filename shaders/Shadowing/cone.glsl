// Shadowing/cone: soft shadows by cone tracing towards each light (cone aperture
// volren_coneAngle) through the opacity mip chain that Shadowing/cone_build.comp writes when
// the TF, the volume or a clip shape changes; no ambient occlusion.
// float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
// float volren_occlusion(vec3 pos, vec3 normal)
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light)
{
    return exp(-volren_coneDepth(pos, lightDir, lightDistance, tan(0.5 * volren_coneAngle))) *
           volren_geometryLight(pos, light);
}

float volren_occlusion(vec3 pos, vec3 normal)
{
    return 1.0;
}
