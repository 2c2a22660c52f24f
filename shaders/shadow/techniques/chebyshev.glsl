// The moments techniques' shared bound (VSM, EVSM). The CPU's copy: renderer/shading/filters/moment_filter.cpp.
// Chebyshev's one-tailed upper bound of the lit share for a receiver at z over moments (mean, E[x^2]).
float chebyshevUpperBound(float mean, float meanSquare, float z, float minVariance) {
    float variance = max(meanSquare - mean * mean, minVariance);
    float d = z - mean;
    float pMax = variance / (variance + d * d);
    return z <= mean ? 1.0 : pMax;
}

// Light-bleeding reduction: shares below `amount` become 0, the rest is rescaled to [0, 1].
float reduceBleeding(float pMax, float amount) { return clamp((pMax - amount) / (1.0 - amount), 0.0, 1.0); }
