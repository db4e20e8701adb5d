// volren shader-function slots: the one place where every slot signature is declared.
// Positions are in volume texture space [0,1]^3 (voxel i's centre at (i+0.5)/n); a ray is
// origin + t*dir with t in [tNear, tFar]. Every slot has a `null` implementation.

// RaySetup: owns main(); builds this fragment's ray, calls the slots below, writes volren_fragColor.

// ClipRay: shortens the ray interval before marching (tNear >= tFar leaves nothing).
void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar);

// Jitter: offset of the first sample as a fraction of one step, in [0,1).
float volren_jitter(vec2 fragCoord);

// RayTraversal: marches [tNear, tFar] and returns premultiplied (associated) RGBA.
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter);

// ClipPosition: true where the sample at pos is clipped away.
bool volren_clipPosition(vec3 pos);

// Reconstruction: the GL texel value (normalised stored scalar) at pos.
float volren_fetchScalar(vec3 pos);

// Classification: texel value -> unassociated RGB and the opacity of one reference segment
// (the smallest voxel spacing). NaN maps to fully transparent.
vec4 volren_classify(float scalar);

// Shading: emitted colour of a classified sample seen along viewDir (towards the eye).
vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified);
