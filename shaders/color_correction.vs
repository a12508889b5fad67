//------------------------------------------------------------------------------
// color_correction.vs: the production vertex shader of the colour-correction
// post-process: one full-screen triangle, with the frame's texture coordinate.
//------------------------------------------------------------------------------
TS_ATTRIBUTE vec2 a_corner;  // (-1,-1), (3,-1), (-1,3)
TS_VARYING vec2 v_uv;

void main() {
    v_uv = a_corner * 0.5 + 0.5;
    gl_Position = vec4(a_corner, 0.0, 1.0);
}
