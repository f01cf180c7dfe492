// common/fullscreen_vertex.glsl -- the vertex shader of every fragment pass: one triangle
// covering the viewport, from gl_VertexIndex alone (draw 3 vertices, no vertex or index
// buffers, no outputs besides gl_Position). Vertices 0, 1, 2 are at clip (-1, -1),
// (3, -1), (-1, 3); z = 0 lies inside every depth convention's range (depth testing is
// off for AO passes anyway). The fragment passes use gl_FragCoord, not interpolated uv.

void main()
{
    vec2 corner = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
