// A surface's material at a hit, unpacked from the material buffer.
struct Surface {
    vec3 baseColor;
    float alpha;
    vec3 emission;       // radiance, emissiveFactor x emissiveStrength
    float roughness;
    float metallic;
    float specular;      // KHR_materials_specular factor; 0 = pure Lambert
    float transmission;
    float ior;
    vec3 specularColor;
    bool thinWalled;     // no KHR_materials_volume thickness: transmission does not bend
    vec3 attenuationCoefficient; // Beer-Lambert sigma inside a volume, per metre
};

const int MATERIAL_FLAG_THIN_WALLED = 1;

Surface fetchSurface(int material) {
    vec4 t0 = materialTexel(material, 0);
    vec4 t1 = materialTexel(material, 1);
    vec4 t2 = materialTexel(material, 2);
    vec4 t3 = materialTexel(material, 3);
    vec4 t4 = materialTexel(material, 4);
    int flags = int(t3.w);
    return Surface(t0.rgb, t0.a, t1.rgb, t1.a, t2.x, t2.y, t2.z, t2.w, t3.rgb,
                   (flags & MATERIAL_FLAG_THIN_WALLED) != 0, t4.rgb);
}
