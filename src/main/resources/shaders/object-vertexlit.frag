#include "vertexlit-fragment.glsl"
