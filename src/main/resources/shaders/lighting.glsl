// Shared sun lighting: hemisphere ambient + Lambert diffuse + Blinn-Phong specular.
uniform vec3 uEye;
uniform vec3 uSunDirection;   // towards the sun, unit length
uniform vec3 uSunColor;
uniform vec3 uSkyAmbient;
uniform vec3 uGroundAmbient;
// The world's air (Atmosphere, from its theme): far things fade into the fog colour.
uniform vec3 uFogColor;
uniform float uFogDensity; // per metre

// occlusion: the share of the sky's light that reaches the point (1 open); it dims the ambient
// light fully and the sun's a little (a contact shade that reads in sunlight too).
vec3 shadeOccluded(vec3 albedo, vec3 n, vec3 worldPos, float specularStrength, float shininess, float sunlight,
                   float occlusion) {
    vec3 v = normalize(uEye - worldPos);
    vec3 l = normalize(uSunDirection);
    vec3 ambient = mix(uGroundAmbient, uSkyAmbient, 0.5 + 0.5 * n.z) * occlusion;
    float diffuse = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    float specular = diffuse > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
    float sun = sunlight * mix(1.0, occlusion, 0.4);
    return albedo * (ambient + uSunColor * diffuse * sun) + uSunColor * specular * specularStrength * sun;
}

vec3 shadeLit(vec3 albedo, vec3 n, vec3 worldPos, float specularStrength, float shininess, float sunlight) {
    return shadeOccluded(albedo, n, worldPos, specularStrength, shininess, sunlight, 1.0);
}

vec3 shade(vec3 albedo, vec3 n, vec3 worldPos, float specularStrength, float shininess) {
    return shadeLit(albedo, n, worldPos, specularStrength, shininess, 1.0);
}

// How much haze lies between the eye and a point d metres away (at most 0.6: Atmosphere.MAX_FOG).
float hazeAmount(float d) {
    return clamp(1.0 - exp(-d * uFogDensity), 0.0, 0.6);
}

// A light haze towards the world's fog colour with distance, so far edges sit in the air.
vec3 haze(vec3 color, vec3 worldPos) {
    return mix(color, uFogColor, hazeAmount(length(uEye - worldPos)));
}
