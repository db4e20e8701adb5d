// RaySetup/box_intersection: owns main(). Entry and exit by ray/box intersection (ray.glsl);
// the proxy draws the box's back faces, so every pixel the box covers casts one ray.
void main()
{
    vec3 origin, dir;
    volren_pixelRay(origin, dir);
    float tNear, tFar;
    volren_boxInterval(origin, dir, tNear, tFar);
    volren_castRay(origin, dir, tNear, tFar);
}
