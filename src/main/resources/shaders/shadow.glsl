// Sun shadows: an orthographic depth map from the sun, sampled with hardware depth comparison
// (sampler2DShadow, linear: each tap is itself a 2x2 bilinear PCF) at four points half a texel and
// a texel apart, which covers a 3x3 texel footprint with 4 taps instead of 9 (cheap on llvmpipe). The receiver's point is
// pushed along its normal by a texel or two (normal offset) so that lit surfaces do not shadow
// themselves (acne) while contact shadows stay attached (no peter-panning).
uniform sampler2DShadow uShadowMap;
uniform mat4 uLightViewProjection;
uniform int uShadowsOn;
uniform float uShadowTexel;     // one shadow-map texel, in texture units
uniform float uShadowNormalOffset; // metres
uniform float uShadowBias;      // depth units

// 1 fully lit, 0 fully in shadow.
float sunVisibility(vec3 worldPos, vec3 n) {
    if (uShadowsOn == 0) return 1.0;
    vec4 p = uLightViewProjection * vec4(worldPos + n * uShadowNormalOffset, 1.0);
    vec3 c = p.xyz / p.w * 0.5 + 0.5;
    if (c.x <= 0.0 || c.x >= 1.0 || c.y <= 0.0 || c.y >= 1.0 || c.z >= 1.0) return 1.0;
    float z = c.z - uShadowBias;
    float t = uShadowTexel;
    float sum = texture(uShadowMap, vec3(c.xy + vec2(-0.5, -0.5) * t, z))
              + texture(uShadowMap, vec3(c.xy + vec2(0.5, -0.5) * t, z))
              + texture(uShadowMap, vec3(c.xy + vec2(-0.5, 0.5) * t, z))
              + texture(uShadowMap, vec3(c.xy + vec2(0.5, 0.5) * t, z));
    return sum * 0.25;
}
