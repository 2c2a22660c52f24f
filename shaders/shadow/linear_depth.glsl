// What a moments map stores of a view's depth, near 0 and far 1: an orthographic view's depth as it is (linear
// already; reversed-Z flipped), a perspective view's (spot, cube face) as its distance along the view's axis,
// normalised by its near and far planes. Perspective window depth crowds near 1, where a caster and its receiver
// differ by too little for a variance (VSM bleeds); the distance does not. The moments pass converts stored depths
// with it and the lookup its receiver. CPU copy: shading/filters/moments_mirror.cpp (momentDepth).
float momentDepth(float window, bool perspective, bool reversed, float near, float far) {
    if (!perspective) return reversed ? 1.0 - window : window;
    float distance = reversed ? near * far / (near + window * (far - near))
                              : 2.0 * far * near / ((far + near) - (2.0 * window - 1.0) * (far - near));
    return (distance - near) / (far - near);
}
