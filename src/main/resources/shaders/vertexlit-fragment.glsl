// The fragment stage of terrain-vertexlit and object-vertexlit: lighting (and, for objects, the haze)
// arrives interpolated from the vertices; only the shadows (shadow.glsl) are computed per pixel.
#include "lighting.glsl"
#include "shadow.glsl"
#ifdef TERRAIN_STRIPES
#include "stripes.glsl"
in float vStripes;
#endif
#ifdef TERRAIN_HAZE
in float vHaze; // the stripes shade the ground's light, not the haze: mixed in here
#endif

in vec3 vWorld;
in vec3 vUnlit;      // without SHADOW_MAP and BALL_SHADOWS: with the sunlight added (the vertex stage)
#if defined(SHADOW_MAP) || defined(BALL_SHADOWS)
in vec3 vSunlit;
in vec3 vShadowCoord;
#endif

out vec4 fragColor;

void main() {
#if defined(SHADOW_MAP) || defined(BALL_SHADOWS)
    float sunlight = mapVisibilityAt(vShadowCoord) * ballVisibility(vWorld);
    vec3 color = vUnlit + vSunlit * sunlight;
#else
    vec3 color = vUnlit;
#endif
    // No material detail here: on llvmpipe one texture-array read per pixel cost the terrain and the
    // obstacles several times their frame (docs/rendering.md); the high tier draws it.
#ifdef TERRAIN_STRIPES
    color *= stripeFactor(vWorld.x, vStripes > 1.5 ? 0.0 : vStripes);
#endif
#ifdef TERRAIN_HAZE
    color = mix(color, uFogColor, vHaze);
#endif
    fragColor = vec4(color, 1.0); // objects: hazed per vertex (object-vertexlit.vert)
}
