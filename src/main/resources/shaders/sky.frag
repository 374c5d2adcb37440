in vec2 vNdc;

uniform mat4 uInverseViewProjection;
uniform vec3 uSunDirection;

out vec4 fragColor;

void main() {
    vec4 nearPoint = uInverseViewProjection * vec4(vNdc, -1.0, 1.0);
    vec4 farPoint = uInverseViewProjection * vec4(vNdc, 1.0, 1.0);
    vec3 dir = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
    float up = dir.z;
    vec3 horizon = vec3(0.80, 0.89, 0.97);
    vec3 zenith = vec3(0.27, 0.52, 0.87);
    vec3 below = vec3(0.55, 0.72, 0.90);
    vec3 color = up >= 0.0 ? mix(horizon, zenith, pow(up, 0.6)) : mix(horizon, below, clamp(-up * 2.5, 0.0, 1.0));
    float s = max(dot(dir, normalize(uSunDirection)), 0.0);
    color += vec3(1.0, 0.95, 0.80) * (pow(s, 600.0) * 1.5 + pow(s, 24.0) * 0.18);
    fragColor = vec4(color, 1.0);
}
