// The terrain's haze per pixel (its stripes shade the light, not the haze). The skirts (SKIRTS: the
// slab's side walls, whose stripe weight is 0, so the stripes' factor is exactly 1) skip the stripes.
#define TERRAIN_HAZE
#ifndef SKIRTS
#define TERRAIN_STRIPES
#endif
#include "vertexlit-fragment.glsl"
