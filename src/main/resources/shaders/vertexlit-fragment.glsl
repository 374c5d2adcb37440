// The fragment stage of terrain-vertexlit and object-vertexlit: lighting arrives interpolated from the
// vertices; only the shadows (shadow.glsl) are computed per pixel.
#include "lighting.glsl"
#include "shadow.glsl"
#ifdef TERRAIN_STRIPES
#include "stripes.glsl"
in float vStripes;
#endif

in vec3 vWorld;
in vec3 vUnlit;
in vec3 vSunlit;
in vec3 vShadowCoord;
in float vHaze;

out vec4 fragColor;

void main() {
    float sunlight = mapVisibilityAt(vShadowCoord) * ballVisibility(vWorld);
    vec3 color = vUnlit + vSunlit * sunlight;
    // No material detail here: on llvmpipe one texture-array read per pixel cost the terrain and the
    // obstacles several times their frame (docs/rendering.md); the high tier draws it.
#ifdef TERRAIN_STRIPES
    color *= stripeFactor(vWorld.x, vStripes > 1.5 ? 0.0 : vStripes);
#endif
    fragColor = vec4(mix(color, uFogColor, vHaze), 1.0);
}
