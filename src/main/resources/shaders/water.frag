#include "lighting.glsl"

in vec3 vWorld;
in float vDepth;

uniform float uTime;

out vec4 fragColor;

void main() {
    vec3 v = normalize(uEye - vWorld);
    // Gentle ripples in the normal only (the surface itself stays flat at z = 0).
    vec2 p = vWorld.xy;
    vec3 n = normalize(vec3(0.020 * sin(p.x * 9.0 + p.y * 4.0 + uTime * 1.3)
                          + 0.012 * sin(p.x * -5.0 + p.y * 11.0 + uTime * 0.9),
                            0.020 * sin(p.y * 8.0 - p.x * 3.0 + uTime * 1.1)
                          + 0.012 * sin(p.y * -6.0 + p.x * 10.0 + uTime * 0.7), 1.0));
    float cosTheta = clamp(dot(n, v), 0.0, 1.0);
    float fresnel = 0.02 + 0.98 * pow(1.0 - cosTheta, 5.0);

    float deep = 1.0 - exp(-vDepth * 20.0);
    vec3 body = mix(vec3(0.10, 0.46, 0.86), vec3(0.02, 0.20, 0.58), deep);
    vec3 sky = vec3(0.62, 0.78, 0.95);
    vec3 color = mix(body, sky, fresnel);
    vec3 h = normalize(normalize(uSunDirection) + v);
    color += uSunColor * pow(max(dot(n, h), 0.0), 180.0) * 0.9;

    float alpha = mix(0.80, 0.95, deep);
    alpha = max(alpha, fresnel);
    alpha *= smoothstep(0.0, 0.004, vDepth); // soft shoreline
    fragColor = vec4(haze(color, vWorld), alpha);
}
