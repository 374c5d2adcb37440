// The fragment stage of terrain-vertexlit and object-vertexlit: lighting arrives interpolated from the
// vertices; only the shadows (shadow.glsl) are computed per pixel.
#include "lighting.glsl"
#include "shadow.glsl"
#include "materials.glsl"
#ifdef TERRAIN_STRIPES
#include "stripes.glsl"
in float vStripes;
#else
in float vMaterial;
#endif
in vec3 vNormal;

in vec3 vWorld;
in vec3 vUnlit;
in vec3 vSunlit;
in vec3 vShadowCoord;
in float vHaze;

out vec4 fragColor;

void main() {
    float sunlight = mapVisibilityAt(vShadowCoord) * ballVisibility(vWorld);
    vec3 color = vUnlit + vSunlit * sunlight;
    // The material's detail, one texture read: the lighting is linear in the albedo, so scaling the
    // lit colour is scaling the albedo (but for the faint specular).
#ifdef TERRAIN_STRIPES
    float grass = vStripes > 1.5 ? 0.0 : vStripes;
    color *= stripeFactor(vWorld.x, grass) * groundDetail(vWorld, vNormal, vStripes).rgb;
#else
    color *= obstacleDetail(vWorld, vNormal, vMaterial).rgb;
#endif
    fragColor = vec4(mix(color, uFogColor, vHaze), 1.0);
}
