//------------------------------------------------------------------------------
// conform_fullscreen.vs: one triangle covering the viewport, used by per-pixel
// conformance runs and by deferred-style (record-driven) frames.
//------------------------------------------------------------------------------
TS_ATTRIBUTE vec2 a_corner;   // (-1,-1), (3,-1), (-1,3)
void main() {
    gl_Position = vec4(a_corner, 0.0, 1.0);
}
