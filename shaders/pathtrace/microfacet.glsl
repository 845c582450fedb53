// GGX (Trowbridge-Reitz) with height-correlated Smith masking, in a local frame (normal = +Z).
float ggxD(vec3 h, float alpha) {
    float a2 = alpha * alpha;
    float c2 = h.z * h.z;
    float d = c2 * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}

float smithLambda(vec3 w, float alpha) {
    float c2 = w.z * w.z;
    float t2 = max(1.0 - c2, 0.0) / max(c2, 1e-12);
    return 0.5 * (-1.0 + sqrt(1.0 + alpha * alpha * t2));
}

float smithG1(vec3 w, float alpha) { return 1.0 / (1.0 + smithLambda(w, alpha)); }

float smithG2(vec3 wo, vec3 wi, float alpha) {
    return 1.0 / (1.0 + smithLambda(wo, alpha) + smithLambda(wi, alpha));
}

// Visible-normal sampling (Heitz 2018, "Sampling the GGX Distribution of Visible Normals").
vec3 sampleGgxVisibleNormal(vec3 wo, float alpha, vec2 u) {
    vec3 v = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
    float lensq = v.x * v.x + v.y * v.y;
    vec3 t1 = lensq > 0.0 ? vec3(-v.y, v.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(v, t1);
    float r = sqrt(u.x);
    float phi = TWO_PI * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + v.z);
    p2 = (1.0 - s) * sqrt(max(1.0 - p1 * p1, 0.0)) + s * p2;
    vec3 n = p1 * t1 + p2 * t2 + sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0)) * v;
    return normalize(vec3(alpha * n.x, alpha * n.y, max(n.z, 1e-6)));
}

// pdf of the reflected direction when h is drawn by sampleGgxVisibleNormal.
float ggxReflectionPdf(vec3 wo, vec3 h, float alpha) {
    return smithG1(wo, alpha) * ggxD(h, alpha) / (4.0 * wo.z);
}

vec3 fresnelSchlick(vec3 f0, float cosTheta) {
    float w = pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
    return f0 + (1.0 - f0) * w;
}

// Unpolarised Fresnel reflectance of a smooth dielectric; eta = n_transmitted / n_incident.
float fresnelDielectric(float cosI, float eta) {
    float sin2T = (1.0 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0) return 1.0; // total internal reflection
    float cosT = sqrt(1.0 - sin2T);
    float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5 * (rs * rs + rp * rp);
}
