// RaySetup/rasterised: owns main(). Entry and exit from the rasterised box (the "colour cube"):
// the pass first draws the box's front faces, storing their volume-space positions in the
// image volren_entryPoints (RaySetup/rasterised_entry.frag); this back-face fragment is the
// exit. Where no front face was stored this frame (the near plane cut it away: camera inside
// the volume), the ray enters at the near plane.
layout(rgba32f, binding = 0) uniform readonly image2D volren_entryPoints;  // bound by the pass

void main()
{
    vec3 origin, dir;
    volren_pixelRay(origin, dir);
    vec4 entry = imageLoad(volren_entryPoints, ivec2(gl_FragCoord.xy - volren_viewportOrigin));
    float tNear = entry.w == volren_frameStamp ? max(volren_rayParameter(origin, dir, entry.xyz), 0.0) : 0.0;
    float tFar = min(volren_rayParameter(origin, dir, volren_vTexCoord), 1.0);
    volren_castRay(origin, dir, tNear, tFar);
}
