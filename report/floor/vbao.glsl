// floor/vbao.glsl -- the fetch floor of vbao.glsl. VBAO reads exactly what GTAO reads (the
// same AO_VBAO_SLICES slices rotated by the noise, AO_VBAO_STEPS samples on each side at
// j / STEPS of the radius in pixels, each a 2x2 gather through ao_depth_at); only its
// arithmetic differs (two angles per sample, a sector mask, a popcount). So this file names
// VBAO's counts as GTAO's, and fetch_floor.hpp appends floor/gtao.glsl's loop after it.

#define AO_GTAO_SLICES AO_VBAO_SLICES
#define AO_GTAO_STEPS AO_VBAO_STEPS
