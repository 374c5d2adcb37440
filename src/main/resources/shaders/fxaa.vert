// FXAA's full-screen quad: the same as the minimap's copy (blit.vert).
#include "blit.vert"
