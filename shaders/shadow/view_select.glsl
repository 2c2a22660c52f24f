// Which of a light's views holds a point: the GLSL mirror of the CPU's views/view_select.cpp (a test checks that
// both, and the hardware's cube lookup, agree on many random points).
// A point light's cube face: the axis of largest magnitude (ties: X, then Y, then Z), its sign's face (>= 0:
// positive), in GL order +X,-X,+Y,-Y,+Z,-Z.
int cubeFaceOf(vec3 d) {
    vec3 a = abs(d);
    int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    return 2 * axis + (d[axis] < 0.0 ? 1 : 0);
}

// The unit axis face `face` looks along.
vec3 cubeFaceAxis(int face) {
    vec3 axis = vec3(0.0);
    axis[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
    return axis;
}

// Which cascade holds a point `depth` in front of the camera: the first whose far depth it is not beyond, and in
// that cascade's blend band (from its blend start) the next one's share. view -1: beyond the last (lit). The CPU's
// selectCascade (views/view_select.cpp) is the same code.
struct CascadeChoice {
    int view;
    int next;
    float weight;
};

CascadeChoice selectCascade(float depth, vec4 farDepths, vec4 blendStarts, int count) {
    CascadeChoice choice = CascadeChoice(-1, -1, 0.0);
    for (int i = 0; i < 4; ++i) {
        if (i >= count || choice.view >= 0 || !(depth <= farDepths[i])) continue;
        choice.view = i;
        if (i + 1 < count && depth > blendStarts[i]) {
            choice.next = i + 1;
            choice.weight = (depth - blendStarts[i]) / (farDepths[i] - blendStarts[i]);
        }
    }
    return choice;
}
