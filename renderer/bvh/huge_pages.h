#pragma once
// Large arrays the BVH build writes once (its items, nodes, flattened buffers) are first touched
// page by page, and on Linux each 4 KiB page is one page fault: about a tenth of a 1 M-triangle
// build's time went to them. Asking for transparent huge pages (2 MiB) over such an array turns
// 512 faults into one. Only advice: where the system does not give huge pages (another OS, THP set
// to "never") nothing changes, and the bytes are the same either way.
#include <cstddef>

namespace glint::bvh {

// Call on memory that is allocated but not yet touched (after reserve(), before the writes).
void adviseHugePages(const void* data, std::size_t bytes);

} // namespace glint::bvh
