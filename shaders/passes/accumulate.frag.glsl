// Exact running mean, mean_n = mean_(n-1) + (x_n - mean_(n-1)) / n, read from the previous target
// and written to the other one (ping-pong: never read and write one texture). Depth (normalDepth.w)
// and object id come from the first sample: their means would mix surfaces. The mean of the squared
// radiance gives each pixel's sample variance (statistical tests, the variance AOV). The specular
// radiance's alpha, the first bounce's reflection distance (0: none), is the first sample's that had
// one: a mean would mix reflected surfaces, and samples without a reflection would pull it to 0.
uniform sampler2D uPreviousRadiance;
uniform sampler2D uPreviousAlbedo;
uniform sampler2D uPreviousNormalDepth;
uniform sampler2D uPreviousObjectId;
uniform sampler2D uPreviousDiffuseAlbedo;
uniform sampler2D uPreviousSpecularAlbedo;
uniform sampler2D uPreviousSpecularRadiance;
uniform sampler2D uPreviousRadianceSquared;
uniform sampler2D uSampleRadiance;
uniform sampler2D uSampleAlbedo;
uniform sampler2D uSampleNormalDepth;
uniform sampler2D uSampleObjectId;
uniform sampler2D uSampleDiffuseAlbedo;
uniform sampler2D uSampleSpecularAlbedo;
uniform sampler2D uSampleSpecularRadiance;
uniform float uSampleCount; // n, counting this sample

out vec4 outRadiance;
out vec4 outAlbedo;
out vec4 outNormalDepth;
out vec4 outObjectId;
out vec4 outDiffuseAlbedo;
out vec4 outSpecularAlbedo;
out vec4 outSpecularRadiance;
out vec4 outRadianceSquared;

vec4 runningMean(vec4 mean, vec4 value) {
    return uSampleCount <= 1.0 ? value : mean + (value - mean) / uSampleCount;
}

vec4 runningMean(sampler2D previous, sampler2D current, ivec2 pixel) {
    return runningMean(texelFetch(previous, pixel, 0), texelFetch(current, pixel, 0));
}

vec4 firstSample(sampler2D previous, sampler2D current, ivec2 pixel) {
    return uSampleCount <= 1.0 ? texelFetch(current, pixel, 0) : texelFetch(previous, pixel, 0);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    outRadiance = runningMean(uPreviousRadiance, uSampleRadiance, pixel);
    outAlbedo = runningMean(uPreviousAlbedo, uSampleAlbedo, pixel);
    vec3 normal = runningMean(uPreviousNormalDepth, uSampleNormalDepth, pixel).xyz;
    outNormalDepth = vec4(normal, firstSample(uPreviousNormalDepth, uSampleNormalDepth, pixel).w);
    outObjectId = firstSample(uPreviousObjectId, uSampleObjectId, pixel);
    outDiffuseAlbedo = runningMean(uPreviousDiffuseAlbedo, uSampleDiffuseAlbedo, pixel);
    outSpecularAlbedo = runningMean(uPreviousSpecularAlbedo, uSampleSpecularAlbedo, pixel);
    outSpecularRadiance = runningMean(uPreviousSpecularRadiance, uSampleSpecularRadiance, pixel);
    float reflectionDistance = firstSample(uPreviousSpecularRadiance, uSampleSpecularRadiance, pixel).a;
    outSpecularRadiance.a = reflectionDistance > 0.0 ? reflectionDistance : texelFetch(uSampleSpecularRadiance, pixel, 0).a;
    vec4 radiance = texelFetch(uSampleRadiance, pixel, 0);
    // Squares of huge (finite) radiance would overflow to Inf: saturate at the largest float.
    outRadianceSquared = runningMean(texelFetch(uPreviousRadianceSquared, pixel, 0), min(radiance * radiance, vec4(3.0e38)));
}
