// Sun shadows. Which parts exist is decided when the program is compiled (ShaderProgram.load with
// defines, see LitShader), not by uniforms: llvmpipe runs both sides of every branch per pixel, so a
// switched-off tap still cost as much as a used one.
//   SHADOW_MAP      sample the sun's depth map of everything that stands still
//   SHADOW_TAPS n   4 (a 3x3-texel footprint, real GPUs) or 1 (one bilinear 2x2 tap, software)
//   BALL_SHADOWS    the balls' analytic soft shadows
// Needs uSunDirection from lighting.glsl (included first).

#ifdef SHADOW_MAP
// An orthographic depth map from the sun, sampled with hardware depth comparison (sampler2DShadow,
// linear: each tap is itself a 2x2 bilinear PCF); four taps half a texel and a texel apart cover a
// 3x3 texel footprint. The receiver's point is pushed along its normal by a texel or two (normal
// offset) so that lit surfaces do not shadow themselves (acne) while contact shadows stay attached.
uniform sampler2DShadow uShadowMap;
uniform mat4 uLightViewProjection;
uniform float uShadowTexel;        // one shadow-map texel, in texture units
uniform float uShadowNormalOffset; // metres
uniform float uShadowBias;         // depth units

// The sun's visibility at shadow-map coordinates c (texture xy, depth z; the receiver already offset).
float mapVisibilityAt(vec3 c) {
    if (c.x <= 0.0 || c.x >= 1.0 || c.y <= 0.0 || c.y >= 1.0 || c.z >= 1.0) return 1.0;
    float z = c.z - uShadowBias;
#if SHADOW_TAPS == 1
    return texture(uShadowMap, vec3(c.xy, z));
#else
    float t = uShadowTexel;
    float sum = texture(uShadowMap, vec3(c.xy + vec2(-0.5, -0.5) * t, z))
              + texture(uShadowMap, vec3(c.xy + vec2(0.5, -0.5) * t, z))
              + texture(uShadowMap, vec3(c.xy + vec2(-0.5, 0.5) * t, z))
              + texture(uShadowMap, vec3(c.xy + vec2(0.5, 0.5) * t, z));
    return sum * 0.25;
#endif
}

float mapVisibility(vec3 worldPos, vec3 n) {
    vec4 p = uLightViewProjection * vec4(worldPos + n * uShadowNormalOffset, 1.0);
    return mapVisibilityAt(p.xyz / p.w * 0.5 + 0.5);
}
#else
float mapVisibilityAt(vec3 c) { return 1.0; }
float mapVisibility(vec3 worldPos, vec3 n) { return 1.0; }
#endif

#ifdef BALL_SHADOWS
// Balls are small and move every frame, so they are not in the (static) shadow map: each casts an
// analytic soft shadow, the distance from its centre to the ray from the receiver towards the sun.
#define MAX_BALL_SHADOWS 8
uniform int uBallCount;
uniform vec4 uBalls[MAX_BALL_SHADOWS]; // centre xyz, radius w

float ballVisibility(vec3 p) {
    float v = 1.0;
    vec3 l = normalize(uSunDirection);
    for (int i = 0; i < uBallCount; i++) {
        vec3 d = uBalls[i].xyz - p;
        float r = uBalls[i].w;
        float s = dot(d, l);
        // Behind the receiver, or the receiver is this ball's own surface (its lit side must stay lit).
        if (s <= 0.0 || dot(d, d) < r * r * 1.1025) continue;
        float miss = length(d - s * l);
        float soft = 0.15 * r + 0.01 * s; // the penumbra widens with distance, as the sun's disc makes it
        v *= smoothstep(r - soft, r + soft, miss);
    }
    return v;
}
#else
float ballVisibility(vec3 p) { return 1.0; }
#endif

// 1 fully lit, 0 fully in shadow.
float sunVisibility(vec3 worldPos, vec3 n) {
    return mapVisibility(worldPos, n) * ballVisibility(worldPos);
}
