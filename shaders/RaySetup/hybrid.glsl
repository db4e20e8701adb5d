// RaySetup/hybrid: owns main(). Exit from the rasterised back face of the box (its interpolated
// volume-space position), entry by ray/box intersection, clamped to the near plane so a camera
// inside the volume works.
void main()
{
    vec3 origin, dir;
    volren_pixelRay(origin, dir);
    float tNear, tFar;
    volren_boxInterval(origin, dir, tNear, tFar);
    tFar = min(volren_rayParameter(origin, dir, volren_vTexCoord), 1.0);
    volren_castRay(origin, dir, tNear, tFar);
}
