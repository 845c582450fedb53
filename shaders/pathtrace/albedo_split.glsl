// The first hit's albedo split by lobe, for the denoiser: metals reflect almost nothing diffusely,
// glass transmits specularly. Approximations (no Fresnel integral): a dielectric's specular layer
// reflects 4 % x its specular factor, a metal its base colour, transmission its base colour.
vec3 diffuseAlbedo(PathResult path) {
    float metallic = path.lobes.x, transmission = path.lobes.z;
    return path.albedo * (1.0 - metallic) * (1.0 - transmission);
}

vec3 specularAlbedo(PathResult path) {
    float metallic = path.lobes.x, transmission = path.lobes.z, specular = path.lobes.w;
    return mix(vec3(0.04 * specular), path.albedo, metallic) + path.albedo * transmission * (1.0 - metallic);
}
