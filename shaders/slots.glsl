// volren shader-function slots: the one place where every slot signature is declared.
// Positions are in volume texture space [0,1]^3 (voxel i's centre at (i+0.5)/n); a ray is
// origin + t*dir with t in [tNear, tFar]. Directions handed to lighting (normal, viewDir,
// lightDir) are unit vectors in the VolumeNode's local axes (world units, spacing applied).
// Every slot has a `null` implementation that does nothing observable.

// RaySetup: owns main(); builds this fragment's ray, calls the slots below, writes volren_fragColor.

// Reconstruction: the GL texel value (normalised stored scalar) at pos. With the pass's debug
// output of sample counts (VOLREN_COUNT_SAMPLES) each call adds one to volren_sampleCount.
float volren_fetchScalar(vec3 pos);

// VolumeStorage: where the voxels of the sampled level live (one 3D texture, or bricks in a
// pool found through a page table). The linearly filtered texel value at pos (clamped to the
// edge voxels), and the texel value of one voxel of the level.
float volren_volumeSample(vec3 pos);
float volren_volumeTexel(ivec3 voxel);

// Classification: texel value -> unassociated RGB and the opacity of one reference segment
// (the smallest voxel spacing). NaN maps to fully transparent.
vec4 volren_classify(float scalar);

// GradientInput: the field whose gradient is taken (raw scalar or classified opacity).
float volren_gradientInput(vec3 pos);

// Gradient: gradient of the GradientInput per world unit, in the node's local axes.
vec3 volren_gradient(vec3 pos);

// Illumination: light reflected towards viewDir by a unit light from lightDir.
vec3 volren_illuminate(vec3 normal, vec3 viewDir, vec3 lightDir, vec3 albedo);

// Shadowing: fraction of light `light` (index into the scene's lights) coming from lightDir that
// reaches pos; the light is lightDistance world units away along lightDir (1e30 for directional
// lights).
float volren_shadow(vec3 pos, vec3 lightDir, float lightDistance, int light);
// And the fraction of the ambient light reaching pos around the unit normal (1: unoccluded).
float volren_occlusion(vec3 pos, vec3 normal);

// Shading: emitted colour of a classified sample seen along viewDir (towards the eye).
vec3 volren_shade(vec3 pos, vec3 viewDir, vec4 classified);

// Weighting: the factor (>= 0) on the opacity of the sample at pos by where it lies in the
// volume (spatial weighting); 1 everywhere for null.
float volren_weight(vec3 pos);

// ClipPosition (template over clip shapes): true where the sample at pos is clipped away.
bool volren_clipPosition(vec3 pos);

// Acceleration: empty-space skipping and adaptive steps. Skipping: a ray parameter t' >= t such
// that no sample in [t, t') may be visible (t itself when the sample at t may be; >= tFar when
// none before tFar may be).
// The answer for t holds for samples up to tRecheck, so traversals ask again only past it.
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck);
// The same for MIP and isosurfaces (above = true) and MinIP: no sample in [t, t') can pass
// level (be > level; for MinIP < level): the ray's running maximum, the float just below the iso
// value, the running minimum.
float volren_skip(vec3 origin, vec3 dir, float t, float tFar, float level, bool above, out float tRecheck);
// Adaptive sampling: how many of the march's steps from the sample at t on one sample may stand
// for, as long as they end by tEnd (1: every step is sampled; the answer holds up to tEnd).
int volren_stepsPerSample(vec3 origin, vec3 dir, float t, out float tEnd);

// Jitter: offset of the first sample as a fraction of one step, in [0,1).
float volren_jitter(vec2 fragCoord);

// ClipRay (template over clip planes): shortens the ray interval before marching.
void volren_clipRay(vec3 origin, vec3 dir, inout float tNear, inout float tFar);

// RayTraversal: marches [tNear, tFar] and returns premultiplied (associated) RGBA; tHit is the
// ray parameter of an opaque surface it found (isosurface), or -1.
vec4 volren_traverse(vec3 origin, vec3 dir, float tNear, float tFar, float jitter, out float tHit);
