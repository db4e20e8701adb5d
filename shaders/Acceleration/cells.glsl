// Acceleration/cells.glsl (included by the grid skippings): the macrocell of a sample and where
// the ray leaves a (coarse) cell. Cell c spans texture coordinates [c, c+1) / volren_cellScale;
// volren_cellCount cells per axis, coarse cells of volren_coarseFactor^3 cells beside them.

// The cell of the sample at t (clamped to the grid).
ivec3 volren_cellAt(vec3 origin, vec3 dir, float t)
{
    return clamp(ivec3(floor((origin + dir * t) * volren_cellScale)), ivec3(0), ivec3(volren_cellCount) - 1);
}

// Where the ray, at t inside the cell of `size` cells whose lowest corner is cell `lower`,
// leaves it: the nearest of the three planes it moves towards (t itself at the latest).
float volren_cellExit(vec3 origin, vec3 dir, float t, vec3 lower, float size)
{
    vec3 planes = (lower + step(vec3(0.0), dir) * size) / volren_cellScale;
    vec3 tPlanes = mix(vec3(1e30), (planes - origin) / dir, notEqual(dir, vec3(0.0)));
    return max(t, min(tPlanes.x, min(tPlanes.y, tPlanes.z)));
}
