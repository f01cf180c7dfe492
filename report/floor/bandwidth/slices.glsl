// floor/bandwidth/slices.glsl -- the bandwidth floor's common/slices.glsl: nothing (the AO
// pass's bandwidth floor reads its pixel's inputs once, and walks no slice).
