#define TERRAIN_STRIPES
#include "vertexlit-fragment.glsl"
