// See sky.vert: the sky's colours arrive interpolated from the grid; per pixel only the clouds
// (CLOUDS: one texture read, the cover's threshold keeps their edges sharp) and the sun's disc
// (SUN_DISC). SkyPass draws the cells that cannot show a cloud (below the horizon) without CLOUDS
// and those far from the sun without SUN_DISC.
in vec3 vSky;
in vec3 vCloudColor;
in vec2 vCloudUv;
in float vCloudLod;
in float vCloudAlpha;
in vec3 vGlow;
in vec3 vDir;

uniform vec3 uSunDirection;
uniform sampler2D uClouds;
uniform float uCloudCover;   // 0 clear .. 1 overcast (the world's)
uniform vec3 uCloudLit;
uniform vec3 uCloudShade;
#if defined(SEA_PIXEL) || defined(GROUND_DETAIL)
uniform vec3 uEye;
uniform vec2 uGround;        // the ground's height, and 1 where it is shown
uniform float uTime;
uniform vec2 uFade;          // as sky.vert's: far away the ground's detail fades with the rest
#endif
#ifdef SEA_PIXEL
in vec3 vSea;
in vec3 vBeach;
in float vFade;              // sky.vert's fade, per vertex (SIMPLE_SHORE)
uniform vec4 uCourseRect;    // the course's bounds: min x, min y, max x, max y
uniform float uShore;        // the shore's distance from the bounds (metres)
#endif
#ifdef GROUND_DETAIL
// The ground round the course shows its material (grass, sand or snow) and soft patches, per pixel,
// fading with distance as its colour does (the cells wholly below the horizon only: SkyPass).
#include "materials.glsl"
uniform float uGroundLayer;
#endif

out vec4 fragColor;

void main() {
    vec3 color = vSky;
#if defined(SEA_PIXEL) || defined(GROUND_DETAIL)
    // Where the ground is seen, the point of the ground plane under this pixel decides its detail and,
    // by the sea, whether it is grass, beach (with a line of foam at the water's edge) or sea.
#ifdef SIMPLE_SHORE
    // The software tier: where the ray meets the ground does not depend on dir's length, and the fade
    // (only the foam's, here) changes slowly enough to come per vertex.
    vec3 dir = vDir;
#else
    vec3 dir = normalize(vDir);
#endif
    if (dir.z < -1e-4 && uGround.y > 0.5 && uEye.z > uGround.x) {
        vec2 p = uEye.xy + dir.xy * ((uGround.x - uEye.z) / dir.z);
#ifdef SIMPLE_SHORE
        float fade = vFade;
#else
        float fade = smoothstep(uFade.x, uFade.y, length(p - uEye.xy));
#endif
        vec3 land = vSky;
#ifdef GROUND_DETAIL
        vec3 detail = mottleAt(p) * materialAt(p * 0.7, uGroundLayer).rgb;
        land *= mix(detail, vec3(1.0), fade);
#endif
        color = land;
#ifdef SEA_PIXEL
        vec2 outside = max(max(uCourseRect.xy - p, p - uCourseRect.zw), 0.0);
        float d = length(outside);
        float grass = 1.0 - smoothstep(uShore - 2.7, uShore - 2.3, d);
        float sea = smoothstep(uShore - 0.1, uShore + 0.1, d);
#ifdef GROUND_DETAIL
        float swell = textureLod(uClouds, p * 0.02 + vec2(uTime * 0.003, 0.0), 2.0).g; // a slow swell (high tier)
        vec3 water = vSea * (0.94 + 0.12 * swell);
#else
        vec3 water = vSea;
#endif
        vec3 ground = mix(mix(vBeach, land, grass), water, sea);
#ifdef SIMPLE_SHORE
        // The same line of foam from a few multiplies (llvmpipe pays for exp and sin on every pixel of the
        // band's cells): sin by a parabola per half wave (within 0.06), exp(-t*t) by (1 - t*t/8)^8.
        float phase = fract((uTime * 0.8 + d) * 0.15915494 + 0.5) - 0.5;
        float swing = 8.0 * phase * (1.0 - 2.0 * abs(phase));
        float t = (d - uShore - 0.25 - 0.15 * swing) * (1.0 / 0.22);
        float bell = max(1.0 - 0.125 * t * t, 0.0);
        bell *= bell;
        bell *= bell;
        float foam = bell * bell * 0.6 * (1.0 - fade);
#else
        float foam = exp(-pow((d - uShore - 0.25 - 0.15 * sin(uTime * 0.8 + d)) / 0.22, 2.0)) * 0.6 * (1.0 - fade);
#endif
        color = mix(ground, vec3(0.95, 0.97, 0.98), foam);
#endif
    }
#endif
#ifdef CLOUDS
    vec2 noise = textureLod(uClouds, vCloudUv, vCloudLod).rg;
    float threshold = 0.76 - 0.5 * uCloudCover;
    float cloud = smoothstep(threshold, threshold + 0.3, noise.r) * vCloudAlpha;
    vec3 cloudColor = mix(uCloudShade, uCloudLit, 0.78 + 0.22 * noise.g) + vCloudColor;
    color = mix(color, cloudColor, cloud);
#endif
#if defined(CLOUDS) || defined(SEA_PIXEL) || defined(GROUND_DETAIL)
    color += vGlow; // else already in vSky (sky.vert)
#endif
#ifdef SUN_DISC
    float s = dot(normalize(vDir), normalize(uSunDirection));
    color += vec3(2.0, 1.9, 1.6) * smoothstep(0.9994, 0.9997, s);
#endif
    fragColor = vec4(color, 1.0);
}
