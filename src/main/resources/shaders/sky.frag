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

out vec4 fragColor;

void main() {
    vec3 color = vSky;
#ifdef CLOUDS
    vec2 noise = textureLod(uClouds, vCloudUv, vCloudLod).rg;
    float cloud = smoothstep(0.53, 0.83, noise.r) * vCloudAlpha;
    vec3 cloudColor = mix(vec3(0.80, 0.83, 0.88), vec3(1.0, 0.99, 0.96), 0.78 + 0.22 * noise.g) + vCloudColor;
    color = mix(color, cloudColor, cloud);
#endif
    color += vGlow;
#ifdef SUN_DISC
    float s = dot(normalize(vDir), normalize(uSunDirection));
    color += vec3(2.0, 1.9, 1.6) * smoothstep(0.9994, 0.9997, s);
#endif
    fragColor = vec4(color, 1.0);
}
