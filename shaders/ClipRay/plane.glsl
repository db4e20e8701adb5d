// ClipRay/plane: shortens the ray to the side of a plane (texture-space equation
// volren_clipRayPlane, kept where dot(n, p) + w >= 0). Template instance.
// void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar)
void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar)
{
    float a = dot(volren_clipRayPlane.xyz, origin) + volren_clipRayPlane.w;
    float b = dot(volren_clipRayPlane.xyz, dir);
    if (b == 0.0) {
        if (a < 0.0) tFar = tNear;  // parallel and outside: nothing left
        return;
    }
    float t = -a / b;
    if (b > 0.0) tNear = max(tNear, t);
    else tFar = min(tFar, t);
}
