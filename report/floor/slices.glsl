// floor/slices.glsl -- the fetch floor of common/slices.glsl: nothing. The floors of gtao.glsl
// and vbao.glsl fetch what those passes fetch without the shared slice arithmetic (their
// surface, radius and slice frame are in floor/gtao.glsl), and common/slices.glsl needs the
// normals.glsl the floor replaces.
