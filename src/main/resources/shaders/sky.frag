// A procedural sky dome: per-pixel view direction from the inverse view-projection, so there are no
// cube-map seams at any resolution. Rayleigh-like gradient (deep blue zenith, pale horizon), the sun's
// disc with a soft halo, and drifting fair-weather clouds: fractal value noise on a cloud layer
// (direction projected onto a plane above), faded out towards the horizon. Below the horizon a hazy
// far distance, darker than the sky, so the course reads as floating above a valley.
in vec2 vNdc;

uniform mat4 uInverseViewProjection;
uniform vec3 uSunDirection;
uniform float uTime;

out vec4 fragColor;

float hash(vec2 p) {
    p = fract(p * vec2(123.34, 456.21));
    p += dot(p, p + 45.32);
    return fract(p.x * p.y);
}

float noise(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash(i), hash(i + vec2(1, 0)), u.x), mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), u.x), u.y);
}

float fbm(vec2 p) {
    float sum = 0.0, amp = 0.5;
    for (int i = 0; i < 4; i++) {
        sum += amp * noise(p);
        p = p * 2.03 + vec2(17.1, 9.2);
        amp *= 0.5;
    }
    return sum;
}

void main() {
    vec4 nearPoint = uInverseViewProjection * vec4(vNdc, -1.0, 1.0);
    vec4 farPoint = uInverseViewProjection * vec4(vNdc, 1.0, 1.0);
    vec3 dir = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
    vec3 sun = normalize(uSunDirection);
    float up = dir.z;
    float s = max(dot(dir, sun), 0.0);

    vec3 horizon = vec3(0.80, 0.88, 0.96);
    vec3 zenith = vec3(0.22, 0.45, 0.82);
    vec3 color;
    if (up >= 0.0) {
        color = mix(horizon, zenith, pow(up, 0.55));
        // Clouds on a layer 1 unit up: uv = dir.xy / dir.z, drifting with time.
        vec2 uv = dir.xy / max(up, 0.04) * 0.9 + vec2(uTime * 0.004, uTime * 0.0025);
        float c = smoothstep(0.50, 0.78, fbm(uv * 1.4));
        float shade = 0.78 + 0.22 * noise(uv * 2.8 + vec2(0.5, 0.7) * sun.xy);
        vec3 cloud = mix(vec3(0.80, 0.83, 0.88), vec3(1.0, 0.99, 0.96), shade) + vec3(1.0, 0.9, 0.7) * pow(s, 8.0) * 0.25;
        color = mix(color, cloud, c * smoothstep(0.02, 0.25, up) * 0.9);
    } else {
        vec3 below = vec3(0.55, 0.70, 0.88);
        color = mix(horizon, below, clamp(-up * 1.6, 0.0, 1.0));
    }
    // The sun: a bright disc, a glow and a broad warm halo.
    color += vec3(1.0, 0.95, 0.80) * (smoothstep(0.9994, 0.9997, s) * 2.0 + pow(s, 300.0) * 0.6 + pow(s, 12.0) * 0.15);
    fragColor = vec4(color, 1.0);
}
