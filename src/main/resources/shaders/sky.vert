// A procedural sky dome, computed at the corners of a screen-covering grid at the far plane (SkyPass):
// the gradient (deep blue zenith, pale horizon), the sun's glow and halo, and drifting fair-weather
// clouds (fractal value noise baked into a tiling texture, CloudNoise, on a cloud layer: the view
// direction projected onto a plane above), faded out towards the horizon. Below the horizon a hazy
// far distance, darker than the sky, so the course reads as floating above a valley. All of that
// varies slowly over the screen, so it is computed per grid corner and interpolated: a software
// rasteriser then pays little per pixel (sky.frag keeps the clouds' edges and the sun's disc sharp).
#include "lighting.glsl"
#include "sky-colour.glsl"

layout(location = 0) in vec2 aNdc;

uniform mat4 uInverseViewProjection;
uniform float uTime;
uniform sampler2D uClouds;
uniform float uCloudPeriod;
uniform float uCloudTexels;  // texels per side of uClouds
uniform vec2 uGridStep;      // one grid cell in NDC
uniform float uGridPixels;   // one grid cell in pixels (about)
// The meadow round the course (SurroundingsPass), a plane at height uGround.x when uGround.y is 1: its
// colour varies slowly over the screen too (flat, unshadowed), so it is computed here per corner
// instead of costing llvmpipe a depth-tested fill of half the screen (about 2 ms a frame).
uniform vec2 uGround;
uniform vec3 uGroundColor;
uniform vec2 uFade;          // horizontal distances over which the meadow fades into the sky
#ifdef SEA
// A seaside world: the ground ends at a beach round the course and the sea reaches to the horizon.
// Their colours are computed here; which of them a pixel shows is decided per pixel (sky.frag,
// SEA_PIXEL) in the cells wholly below the horizon, per corner in the others (they lie far away).
uniform vec3 uSeaColor;
uniform vec3 uBeachColor;
uniform vec4 uCourseRect;    // the course's bounds: min x, min y, max x, max y
uniform float uShore;        // the shore's distance from the bounds (metres)
out vec3 vSea;
out vec3 vBeach;
out float vFade;      // the ground's fade into the sky here (sky.frag's foam, SIMPLE_SHORE)
#endif

out vec3 vSky;        // gradient under the clouds
out vec3 vCloudColor; // the sun's warm tint on the clouds here
out vec2 vCloudUv;    // where the cloud texture is read, per pixel
out float vCloudLod;  // at which mip level
out float vCloudAlpha;// how much cloud shows (fades towards the horizon; none below it)
out vec3 vGlow;       // the sun's glow and halo, over the clouds
out vec3 vDir;        // the view direction, for the sun's disc per pixel

vec3 directionAt(vec2 ndc) {
    vec4 nearPoint = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 farPoint = uInverseViewProjection * vec4(ndc, 1.0, 1.0);
    return normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
}

// Clouds on a layer 1 unit up: dir.xy / dir.z, drifting with time; in texture units.
vec2 cloudUv(vec3 dir) {
    vec2 uv = dir.xy / max(dir.z, 0.04) * 0.9 + vec2(uTime * 0.004, uTime * 0.0025);
    return uv * 1.4 / uCloudPeriod;
}

void main() {
    vec3 dir = directionAt(aNdc);
    vec3 sun = normalize(uSunDirection);
    float up = dir.z;
    float s = max(dot(dir, sun), 0.0);

    vSky = skyGradient(dir);
    vGlow = sunGlow(s);
    vec4 nearPoint = uInverseViewProjection * vec4(aNdc, -1.0, 1.0);
    vec3 origin = nearPoint.xyz / nearPoint.w;
#ifdef SEA
    vSea = vSky;
    vBeach = vSky;
    vFade = 1.0;
#endif
    if (uGround.y > 0.5 && up < 0.0 && origin.z > uGround.x) {
        vec3 p = origin + dir * ((uGround.x - origin.z) / up);
        vec3 lit = haze(shade(uGroundColor, vec3(0.0, 0.0, 1.0), p, 0.03, 8.0), p);
        float f = smoothstep(uFade.x, uFade.y, length(p.xy - uEye.xy));
#ifdef SEA
        // The sea: the sky mirrored (Fresnel) over deep water, and a broad glint towards the sun.
        vec3 r = reflect(dir, vec3(0.0, 0.0, 1.0));
        float fresnel = 0.02 + 0.98 * pow(1.0 - max(-up, 0.0), 5.0);
        vec3 sea = mix(uSeaColor * (uSkyAmbient + uSunColor * 0.35), skyGradient(r), clamp(fresnel * 1.2, 0.0, 1.0));
        sea += uSunColor * pow(max(dot(r, sun), 0.0), 40.0) * 0.35;
        vSea = mix(haze(sea, p), vSky, f);
        vBeach = mix(haze(shade(uBeachColor, vec3(0.0, 0.0, 1.0), p, 0.03, 8.0), p), vSky, f);
        vFade = f;
#ifndef SEA_PIXEL
        vec2 outside = max(max(uCourseRect.xy - p.xy, p.xy - uCourseRect.zw), 0.0);
        if (length(outside) > uShore) lit = haze(sea, p);
#endif
#endif
        vSky = mix(lit, vSky, f);
        vGlow *= f; // the fragment adds it: mix(lit, sky + glow, f) in all
    }

    // The noise is read at a mip level as coarse as the grid: finer detail could not be interpolated anyway.
    vec2 uv = cloudUv(dir);
    vec2 du = cloudUv(directionAt(aNdc + vec2(uGridStep.x, 0.0))) - uv;
    vec2 dv = cloudUv(directionAt(aNdc + vec2(0.0, uGridStep.y))) - uv;
    vCloudLod = log2(max(max(length(du), length(dv)) * uCloudTexels / uGridPixels, 1.0));
    vCloudUv = uv;
    vCloudColor = vec3(1.0, 0.9, 0.7) * pow(s, 8.0) * 0.25;
    vCloudAlpha = up >= 0.0 ? smoothstep(0.02, 0.25, up) * 0.9 : 0.0;
    vDir = dir;
#if !defined(CLOUDS) && !defined(SEA_PIXEL) && !defined(GROUND_DETAIL)
    // Nothing per pixel goes between the gradient and the glow: one colour to interpolate (sky.frag).
    vSky += vGlow;
#endif
    gl_Position = vec4(aNdc, 1.0, 1.0);
}
