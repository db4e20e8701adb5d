// Acceleration/occupancy: TF-aware empty-space skipping over the macrocell occupancy grid; the
// leap is Acceleration/occupancy_leap.glsl, every visible sample is taken
// (Acceleration/every_step.glsl), so this file adds nothing of its own.
// float volren_skip(vec3 origin, vec3 dir, float t, float tFar, out float tRecheck)
// int volren_stepsPerSample(...): Acceleration/every_step.glsl
