// Shared sun lighting: hemisphere ambient + Lambert diffuse + Blinn-Phong specular.
uniform vec3 uEye;
uniform vec3 uSunDirection;   // towards the sun, unit length
uniform vec3 uSunColor;
uniform vec3 uSkyAmbient;
uniform vec3 uGroundAmbient;

vec3 shadeLit(vec3 albedo, vec3 n, vec3 worldPos, float specularStrength, float shininess, float sunlight) {
    vec3 v = normalize(uEye - worldPos);
    vec3 l = normalize(uSunDirection);
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.z);
    float diffuse = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
    return albedo * (ambient + uSunColor * diffuse * sunlight) + uSunColor * specular * specularStrength * sunlight;
}

vec3 shade(vec3 albedo, vec3 n, vec3 worldPos, float specularStrength, float shininess) {
    return shadeLit(albedo, n, worldPos, specularStrength, shininess, 1.0);
}

// A light haze towards the horizon colour with distance, so far edges sit in the air.
vec3 haze(vec3 color, vec3 worldPos) {
    float d = length(uEye - worldPos);
    float f = 1.0 - exp(-d * 0.004);
    return mix(color, vec3(0.78, 0.87, 0.96), clamp(f, 0.0, 0.6));
}
