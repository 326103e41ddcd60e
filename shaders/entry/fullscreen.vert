#version 450 core
// One triangle that covers the viewport: vertices (-1,-1), (3,-1), (-1,3).
// Defines set by the host: none used. Compiled with trace.frag it receives the tracer's defines
// and ignores them.
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
