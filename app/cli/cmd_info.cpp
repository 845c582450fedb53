// glint info FILE [--json]: what a scene holds, and what is wrong with it.
#include "command.h"
#include "exit_codes.h"
#include "report.h"
#include "scene_file.h"
#include "scene_summary.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace glint::cli {

namespace {

nlohmann::json namedItems(const std::vector<NamedItem>& items) {
    auto out = nlohmann::json::array();
    for (const auto& i : items) out.push_back({{"name", i.name}, {"kind", i.kind}});
    return out;
}

nlohmann::json toJson(const std::string& file, const SceneSummary& s, const Warnings& warnings) {
    nlohmann::json j;
    j["file"] = file;
    j["nodes"] = s.nodes;
    j["meshes"] = nlohmann::json::array();
    for (const auto& m : s.meshes)
        j["meshes"].push_back({{"name", m.name}, {"triangles", m.triangles}, {"instances", m.instances}});
    j["triangles"] = {{"unique", s.uniqueTriangles}, {"instanced", s.instancedTriangles}};
    j["shapes"] = namedItems(s.shapes);
    j["materials"] = s.materials;
    j["textures"] = s.textures;
    j["images"] = s.images;
    j["lights"] = namedItems(s.lights);
    j["cameras"] = namedItems(s.cameras);
    j["animations"] = nlohmann::json::array();
    for (const auto& a : s.animations)
        j["animations"].push_back({{"name", a.name}, {"channels", a.channels}, {"start", a.start}, {"end", a.end}});
    j["cameraPaths"] = nlohmann::json::array();
    for (const auto& p : s.cameraPaths)
        j["cameraPaths"].push_back({{"node", p.node}, {"keys", p.keys}, {"start", p.start}, {"end", p.end}});
    j["warnings"] = nlohmann::json::array();
    for (const auto& w : warnings) j["warnings"].push_back({{"file", w.file}, {"code", w.code}, {"message", w.message}});
    return j;
}

std::string joinItems(const std::vector<NamedItem>& items) {
    std::string out;
    for (const auto& i : items) out += (out.empty() ? "" : ", ") + i.name + " (" + i.kind + ")";
    return out.empty() ? "-" : out;
}

void printText(const std::string& file, const SceneSummary& s, const Warnings& warnings) {
    std::printf("file:        %s\n", file.c_str());
    std::printf("nodes:       %zu\n", s.nodes);
    std::printf("meshes:      %zu\n", s.meshes.size());
    for (const auto& m : s.meshes)
        std::printf("  %-24s %10zu triangles x %zu\n", m.name.empty() ? "(unnamed)" : m.name.c_str(), m.triangles, m.instances);
    std::printf("triangles:   %zu unique, %zu instanced\n", s.uniqueTriangles, s.instancedTriangles);
    std::printf("shapes:      %s\n", joinItems(s.shapes).c_str());
    std::printf("materials:   %zu\n", s.materials.size());
    std::printf("textures:    %zu (%zu images)\n", s.textures, s.images);
    std::printf("lights:      %s\n", joinItems(s.lights).c_str());
    std::printf("cameras:     %s\n", joinItems(s.cameras).c_str());
    std::printf("animations:  %zu\n", s.animations.size());
    for (const auto& a : s.animations)
        std::printf("  %-24s %zu channels, %g s to %g s\n", a.name.empty() ? "(unnamed)" : a.name.c_str(), a.channels, a.start, a.end);
    std::printf("camera paths: %zu\n", s.cameraPaths.size());
    for (const auto& p : s.cameraPaths)
        std::printf("  %-24s %zu keys, %g s to %g s\n", p.node.c_str(), p.keys, p.start, p.end);
    std::printf("warnings:    %zu\n", warnings.size());
}

struct InfoOptions {
    std::string file;
    bool json = false;
    bool strict = false;
};

int runInfo(const InfoOptions& o) {
    LoadResult loaded = openSceneFile(o.file);
    SceneSummary summary = summarize(loaded.scene);
    if (o.json)
        std::cout << toJson(o.file, summary, loaded.warnings).dump(2) << '\n';
    else
        printText(o.file, summary, loaded.warnings);
    std::cout.flush();
    return reportWarnings(loaded.warnings, o.strict) ? kFailure : kSuccess;
}

} // namespace

void addInfoCommand(CLI::App& app, Action& action) {
    auto options = std::make_shared<InfoOptions>();
    CLI::App* cmd = app.add_subcommand("info", "Describe a scene: nodes, meshes, triangles, materials, lights, "
                                               "cameras, animations, camera paths and warnings.");
    cmd->add_option("FILE", options->file, "Scene: .gltf, .glb, .glint.json, or any format convert imports")->required();
    cmd->add_flag("--json", options->json, "Machine-readable output on stdout (default: off)");
    cmd->add_flag("--strict", options->strict, "Treat warnings as failures (default: off)");
    cmd->callback([options, &action] { action = [options] { return runInfo(*options); }; });
}

} // namespace glint::cli
