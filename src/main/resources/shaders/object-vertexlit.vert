// Objects and obstacles for software rasterisers (RenderQuality.SOFTWARE), as terrain-vertexlit:
// the sun's lighting and the haze per vertex, only the shadows per pixel (object-vertexlit.frag).
// Obstacle faces are flat, so per-vertex diffuse light is the same as per-pixel there.
#include "lighting.glsl"
#include "wind.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 aColor; // rgb and the material's id (meshes with rgb only read 1: plain)

uniform mat4 uViewProjection;
uniform vec4 uClipPlane;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uLightViewProjection;
uniform float uShadowNormalOffset;
uniform float uSpecularStrength;
uniform float uShininess;
uniform vec3 uTint;

out vec3 vWorld;
out vec3 vUnlit;     // ambient part, never shadowed, with the haze (all of the fog's colour)
out vec3 vSunlit;    // sun diffuse + specular, hazed, scaled by the sun's visibility per pixel
out vec3 vShadowCoord;

// The balls' shadows redraw these surfaces within a scissor at GL_LEQUAL (SceneRenderer): the depth must match exactly.
invariant gl_Position;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vec3 n = normalize(uNormalMatrix * aNormal);
    waveCloth(aColor.a, world.xyz, n);
    // Thin things (the flag's cloth) are seen from both sides.
    if (dot(n, uEye - world.xyz) < 0.0) n = -n;
    vec3 v = normalize(uEye - world.xyz);
    vec3 l = normalize(uSunDirection);
    vec3 albedo = aColor.rgb * uTint;
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.z);
    float diffuse = max(dot(n, l), 0.0);
    float specular = diffuse > 0.0 ? pow(max(dot(n, normalize(l + v)), 0.0), uShininess) : 0.0;
    // The haze is linear in the colour, so it is applied here: mix(unlit + sunlit * s, fog, h) is
    // mix(unlit, fog, h) + sunlit * (1 - h) * s, and the fragment stage keeps one multiply-add.
    float haze = hazeAmount(length(uEye - world.xyz));
    vUnlit = mix(albedo * ambient, uFogColor, haze);
    vSunlit = (albedo * uSunColor * diffuse + uSunColor * specular * uSpecularStrength) * (1.0 - haze);
#if !defined(SHADOW_MAP) && !defined(BALL_SHADOWS)
    // Nothing shadows this draw (sunlit cells, faces turned from the sun, shadows off): the sunlight is
    // added here, and the fragment stage interpolates three inputs fewer (vertexlit-fragment.glsl).
    vUnlit += vSunlit;
#endif
    vec4 p = uLightViewProjection * vec4(world.xyz + n * uShadowNormalOffset, 1.0);
    vShadowCoord = p.xyz / p.w * 0.5 + 0.5;
    vWorld = world.xyz;
    gl_ClipDistance[0] = dot(uClipPlane, world);
    gl_Position = uViewProjection * world;
}
