// Extensions and extras on objects that Glint rebuilds on save instead of keeping (camera
// projections, lights, buffers, accessors, animation channels, the parts of materials that are
// plain values): named once at load and again by the next save, so nothing is lost silently.
#include "gltf_reader.h"

#include <string_view>

namespace glint {

namespace {

// More than this many places are summed up in one last warning: a file with extras on every
// accessor should not bury the other warnings.
constexpr int kMaxNamedPlaces = 16;

struct DroppedMembers {
    GltfReadContext& ctx;
    int named = 0;
    int unnamed = 0;

    void check(const nlohmann::json& object, const std::string& where, std::initializer_list<std::string_view> kept = {})
    {
        if (!object.is_object()) return;
        std::string what;
        if (auto it = object.find("extensions"); it != object.end() && it->is_object()) {
            for (const auto& [name, value] : it->items()) {
                bool isKept = false;
                for (std::string_view k : kept) isKept = isKept || name == k;
                if (!isKept) what += (what.empty() ? "extension " : ", extension ") + name;
            }
        }
        if (object.contains("extras")) what += what.empty() ? "extras" : ", extras";
        if (what.empty()) return;
        if (named++ < kMaxNamedPlaces) ctx.drop("extension-dropped", where + " has " + what + ", which Glint does not keep");
        else ++unnamed;
    }

    void checkEach(const char* array, std::initializer_list<std::string_view> kept = {})
    {
        const auto it = ctx.doc.find(array);
        if (it == ctx.doc.end() || !it->is_array()) return;
        for (std::size_t i = 0; i < it->size(); ++i) check((*it)[i], std::string(array) + "[" + std::to_string(i) + "]", kept);
    }

    void checkMember(const nlohmann::json& parent, const char* key, const std::string& where)
    {
        if (auto it = parent.find(key); it != parent.end()) check(*it, where + "." + key);
    }

    void summarise()
    {
        if (unnamed > 0)
            ctx.drop("extension-dropped", std::to_string(unnamed) + " more objects have extensions or extras that Glint does not keep");
    }
};

void checkCameras(DroppedMembers& d)
{
    d.checkEach("cameras", {"GLINT_camera"});
    const auto cameras = d.ctx.doc.find("cameras");
    if (cameras == d.ctx.doc.end() || !cameras->is_array()) return;
    for (std::size_t i = 0; i < cameras->size(); ++i) {
        const std::string where = "cameras[" + std::to_string(i) + "]";
        if (!(*cameras)[i].is_object()) continue;
        d.checkMember((*cameras)[i], "perspective", where);
        d.checkMember((*cameras)[i], "orthographic", where);
    }
}

void checkLights(DroppedMembers& d)
{
    const auto ext = d.ctx.doc.find("extensions");
    if (ext == d.ctx.doc.end() || !ext->is_object()) return;
    const auto punctual = ext->find("KHR_lights_punctual");
    if (punctual == ext->end() || !punctual->is_object()) return;
    const auto lights = punctual->find("lights");
    if (lights == punctual->end() || !lights->is_array()) return;
    for (std::size_t i = 0; i < lights->size(); ++i) {
        const std::string where = "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]";
        d.check((*lights)[i], where, {"GLINT_light"});
        if ((*lights)[i].is_object()) d.checkMember((*lights)[i], "spot", where);
    }
}

void checkMaterials(DroppedMembers& d)
{
    const auto materials = d.ctx.doc.find("materials");
    if (materials == d.ctx.doc.end() || !materials->is_array()) return;
    for (std::size_t i = 0; i < materials->size(); ++i) {
        const nlohmann::json& m = (*materials)[i];
        if (!m.is_object()) continue;
        const std::string where = "materials[" + std::to_string(i) + "]";
        d.checkMember(m, "pbrMetallicRoughness", where);
        const auto ext = m.find("extensions");
        if (ext == m.end() || !ext->is_object()) continue;
        for (const char* name : {"KHR_materials_emissive_strength", "KHR_materials_specular", "KHR_materials_transmission",
                                 "KHR_materials_ior", "KHR_materials_volume", "GLINT_materials_volume_scatter"})
            d.checkMember(*ext, name, where + ".extensions");
    }
}

void checkAnimationParts(DroppedMembers& d)
{
    const auto animations = d.ctx.doc.find("animations");
    if (animations == d.ctx.doc.end() || !animations->is_array()) return;
    for (std::size_t i = 0; i < animations->size(); ++i) {
        const nlohmann::json& a = (*animations)[i];
        if (!a.is_object()) continue;
        for (const char* part : {"channels", "samplers"}) {
            const auto list = a.find(part);
            if (list == a.end() || !list->is_array()) continue;
            for (std::size_t k = 0; k < list->size(); ++k)
                d.check((*list)[k], "animations[" + std::to_string(i) + "]." + part + "[" + std::to_string(k) + "]");
        }
    }
}

// The other scenes are dropped whole, and named so, when the node graph is read.
void checkDefaultScene(DroppedMembers& d)
{
    const auto scenes = d.ctx.doc.find("scenes");
    if (scenes == d.ctx.doc.end() || !scenes->is_array() || scenes->empty()) return;
    const auto chosen = d.ctx.doc.find("scene");
    const std::size_t index = chosen != d.ctx.doc.end() && chosen->is_number_unsigned() ? chosen->get<std::size_t>() : 0;
    if (index < scenes->size()) d.check((*scenes)[index], "scenes[" + std::to_string(index) + "]");
}

} // namespace

void noteDroppedMembers(GltfReadContext& ctx)
{
    DroppedMembers d{ctx};
    checkDefaultScene(d);
    d.checkEach("buffers");
    d.checkEach("bufferViews");
    d.checkEach("accessors");
    checkCameras(d);
    checkLights(d);
    checkMaterials(d);
    checkAnimationParts(d);
    d.summarise();
}

} // namespace glint
