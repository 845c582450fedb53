// A binary search among records sorted by object id in a buffer texture, `stride` texels per record
// with the id in the first texel's x: the motion pass's moved instances, the selection outline's
// ids. So any number of them costs a shader no uniform array.

// The index of the record of `id` among the first `count`, or -1.
int sortedIdIndex(samplerBuffer records, int count, int stride, float id) {
    int low = 0;
    int high = count - 1;
    while (low <= high) {
        int middle = (low + high) / 2;
        float at = texelFetch(records, middle * stride).x;
        if (abs(at - id) < 0.5) return middle;
        if (at < id) low = middle + 1;
        else high = middle - 1;
    }
    return -1;
}
