// BVH benchmark (a program, not a test): build time and SAH cost for the bunny (~70k triangles)
// and subdivided bunnies (~1.1M, ~4.4M) with 1 and 2 build threads, and CPU closest-hit rays/s.
// Usage: bench_bvh OUTPUT_DIR [REPEATS]   writes OUTPUT_DIR/bvh_bench.csv and bvh_bench.json.
#include "bvh_test_scenes.h"
#include "renderer/bvh/traverse.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace glint::bvh;
using namespace glint::bvh::test;

namespace {

struct Row {
    std::string mesh;
    std::size_t triangles = 0;
    int threads = 0;
    double buildMs = 0.0;    // median, wall clock
    double buildCpuMs = 0.0; // median, CPU time of all threads
    double sah = 0.0;
    int depth = 0;
    std::size_t nodes = 0;
    std::uint64_t tree = 0;     // FNV-1a of the nodes and the item order: equal trees, equal values
    double raysPerSecond = 0.0; // median per CPU second; single-threaded closest hit, 0 when not measured
    double hitFraction = 0.0;   // of the random rays through the mesh's box
};

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// Wall time and process CPU time (all threads): on a shared machine the CPU time of a
// single-threaded run is the steadier figure; the wall time shows what threads gain.
struct Stopwatch {
    std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
    std::clock_t cpu = std::clock();
    double wallSeconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(); }
    double cpuSeconds() const { return static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC; }
};

// FNV-1a over the bytes of the nodes and the item order, so two builds can be compared by eye.
std::uint64_t treeHash(const Bvh& bvh)
{
    std::uint64_t hash = 1469598103934665603ull;
    const auto add = [&](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
    };
    for (const BvhNode& node : bvh.nodes) {
        add(&node.bounds, sizeof(node.bounds));
        add(&node.first, sizeof(node.first));
        add(&node.count, sizeof(node.count));
    }
    add(bvh.itemOrder.data(), bvh.itemOrder.size() * sizeof(std::uint32_t));
    return hash;
}

double measureRays(const MeshBvh& mesh, int repeats, double& hitFraction)
{
    const TestScene scene{{}, {}, buildTopLevel({Instance{}}, {mesh}), {}};
    const FlatScene flat = flattenScene({mesh}, scene.topLevel);
    std::mt19937 rng(5u);
    std::vector<Ray> rays(200000);
    for (Ray& ray : rays) ray = randomRayThrough(rng, mesh.bounds());
    std::vector<double> rates;
    for (int r = 0; r < repeats; ++r) {
        const Stopwatch watch;
        std::size_t hits = 0;
        for (const Ray& ray : rays) hits += intersectClosest(flat, ray, 1e30f).hit() ? 1 : 0;
        rates.push_back(static_cast<double>(rays.size()) / watch.cpuSeconds());
        hitFraction = static_cast<double>(hits) / static_cast<double>(rays.size());
    }
    return median(rates);
}

Row measureBuild(const std::string& name, const MeshTriangles& triangles, int threads, int repeats, bool rays)
{
    Row row{name, triangles.triangleCount(), threads};
    BuildOptions options;
    options.threads = threads;
    std::vector<double> wallTimes, cpuTimes;
    MeshBvh mesh;
    for (int r = 0; r < repeats; ++r) {
        MeshTriangles input = triangles; // the copy is not timed
        const Stopwatch watch;
        mesh = buildMeshBvh(std::move(input), options);
        wallTimes.push_back(1000.0 * watch.wallSeconds());
        cpuTimes.push_back(1000.0 * watch.cpuSeconds());
    }
    row.buildMs = median(wallTimes);
    row.buildCpuMs = median(cpuTimes);
    row.sah = sahCost(mesh.bvh);
    row.depth = maxDepth(mesh.bvh);
    row.nodes = mesh.bvh.nodes.size();
    row.tree = treeHash(mesh.bvh);
    if (rays) row.raysPerSecond = measureRays(mesh, repeats, row.hitFraction);
    return row;
}

void writeFiles(const std::filesystem::path& dir, const std::vector<Row>& rows, int repeats)
{
    std::filesystem::create_directories(dir);
    std::ofstream csv(dir / "bvh_bench.csv");
    csv << "mesh,triangles,threads,build_ms_median,build_cpu_ms_median,sah_cost,depth,nodes,tree_fnv1a,rays_per_cpu_s_median,ray_hit_fraction\n";
    std::ofstream json(dir / "bvh_bench.json");
    json << "{\n  \"repeats\": " << repeats << ",\n  \"results\": [\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        csv << r.mesh << ',' << r.triangles << ',' << r.threads << ',' << r.buildMs << ',' << r.buildCpuMs << ',' << r.sah << ',' << r.depth << ','
            << r.nodes << ',' << std::hex << r.tree << std::dec << ',' << r.raysPerSecond << ',' << r.hitFraction << '\n';
        json << "    {\"mesh\": \"" << r.mesh << "\", \"triangles\": " << r.triangles << ", \"threads\": " << r.threads
             << ", \"build_ms_median\": " << r.buildMs << ", \"build_cpu_ms_median\": " << r.buildCpuMs << ", \"sah_cost\": " << r.sah << ", \"depth\": " << r.depth
             << ", \"nodes\": " << r.nodes << ", \"tree_fnv1a\": \"" << std::hex << r.tree << std::dec << "\", \"rays_per_cpu_s_median\": " << r.raysPerSecond << ", \"ray_hit_fraction\": " << r.hitFraction << "}"
             << (i + 1 < rows.size() ? "," : "") << '\n';
    }
    json << "  ]\n}\n";
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_bvh OUTPUT_DIR [REPEATS]\n");
        return 2;
    }
    const int repeats = argc > 2 ? std::max(1, std::stoi(argv[2])) : 5;
    const MeshTriangles bunny = loadBunny();
    const MeshTriangles bunny1m = subdivided(bunny, 2);
    const MeshTriangles bunny4m = subdivided(bunny, 3);
    std::vector<Row> rows;
    for (int threads : {1, 2}) {
        rows.push_back(measureBuild("bunny", bunny, threads, repeats, threads == 1));
        rows.push_back(measureBuild("bunny_x16", bunny1m, threads, repeats, threads == 1));
        rows.push_back(measureBuild("bunny_x64", bunny4m, threads, std::min(repeats, 3), threads == 1));
    }
    std::printf("%-10s %10s %7s %10s %10s %12s %8s %6s %10s %16s %12s\n", "mesh", "triangles", "threads", "build ms", "cpu ms",
                "Mtri/cpu-s", "SAH", "depth", "nodes", "tree", "rays/cpu-s");
    for (const Row& r : rows)
        std::printf("%-10s %10zu %7d %10.1f %10.1f %12.2f %8.3f %6d %10zu %16llx %12.0f\n", r.mesh.c_str(), r.triangles, r.threads,
                    r.buildMs, r.buildCpuMs, r.buildCpuMs > 0.0 ? 1e-3 * static_cast<double>(r.triangles) / r.buildCpuMs : 0.0, r.sah,
                    r.depth, r.nodes, static_cast<unsigned long long>(r.tree), r.raysPerSecond);
    writeFiles(argv[1], rows, repeats);
    return 0;
}
