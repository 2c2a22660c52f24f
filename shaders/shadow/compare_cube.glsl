// What a point light's cube-map comparisons share (lookup_cube.glsl's filters and PCSS's techniques/pcss.glsl): the
// comparison samplers, read with constant indices.
#if MAP_ARRAYS_CUBE > 0
uniform samplerCubeArrayShadow uMapsCube[MAP_ARRAYS_CUBE];
#endif

// Map arrays are read with constant indices only (see shadow/compare_2d.glsl).
#if MAP_ARRAYS_CUBE > 0
float sampleMapCube(int map, vec4 coord, float ref) {
#if MAP_ARRAYS_CUBE == 1
    return texture(uMapsCube[0], coord, ref);
#else
    float result = 1.0;
    for (int k = 0; k < MAP_ARRAYS_CUBE; ++k)
        if (k == map) result = texture(uMapsCube[k], coord, ref);
    return result;
#endif
}
#endif
