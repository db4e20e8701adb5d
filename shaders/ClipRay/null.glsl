// ClipRay/null: leaves the ray interval unchanged.
// void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar)
void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar)
{
}
