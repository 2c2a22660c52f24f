uniform float uFilterScale;    // tap offsets are multiplied by it (Poisson: the radius; grids: 1)

// The filter's taps: a square grid (FILTER_GRID_RADIUS: offsets -R..R, row by row, as loops a compiler unrolls) or
// a list (FILTER_TAP_OFFSETS). Large constant arrays are slow on some drivers (llvmpipe: 81 taps 1.7x).
#ifdef FILTER_GRID_RADIUS
#define FOR_EACH_TAP for (int ty = -FILTER_GRID_RADIUS; ty <= FILTER_GRID_RADIUS; ++ty) \
                     for (int tx = -FILTER_GRID_RADIUS; tx <= FILTER_GRID_RADIUS; ++tx)
#define TAP_OFFSET vec2(tx, ty)
#else
const vec2 TAP_OFFSETS[FILTER_TAPS] = vec2[](FILTER_TAP_OFFSETS);
#define FOR_EACH_TAP for (int ti = 0; ti < FILTER_TAPS; ++ti)
#define TAP_OFFSET TAP_OFFSETS[ti]
#endif

