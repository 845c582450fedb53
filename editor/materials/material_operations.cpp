#include "material_operations.h"
#include "editor/document/in_macro.h"

#include "editor/document/labelled_command.h"
#include "scene/history/asset_commands.h"
#include "scene/history/material_commands.h"
#include "scene/history/set_node_field.h"
#include "scene/io/image_decoder.h"
#include "scene/io/oiio/oiio_image_decoder.h"

#include <QCoreApplication>
#include <QFile>
#include <QDataStream>
#include <QFileInfo>
#include <QIODevice>
#include <QMimeData>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <exception>
#include <set>
#include <span>

namespace glint::editor {
namespace {

namespace OIIO = OIIO_NAMESPACE;

// The labels these edits give their commands, in the history's context so the undo history
// translates them (history_view/command_labels.h).
[[maybe_unused]] constexpr const char* kLabels[] = {
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "New material"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Duplicate material"),
    QT_TRANSLATE_NOOP("glint::editor::CommandLabels", "Assign material"),
};

QString tr(const char* text) { return QCoreApplication::translate("glint::editor::MaterialOperations", text); }

QString pushOne(Document& document, CommandPtr command) {
    try {
        document.push(std::move(command));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

MaterialId pushMaterial(Document& document, Material value) {
    auto command = std::make_unique<AddAsset<Material>>(std::move(value));
    AddAsset<Material>* raw = command.get();
    document.push(withLabel(std::move(command), "New material"));
    return raw->id();
}

template <class T>
auto pushAsset(Document& document, T value) {
    auto command = std::make_unique<AddAsset<T>>(std::move(value));
    AddAsset<T>* raw = command.get();
    document.push(std::move(command));
    return raw->id();
}

constexpr TextureSlot kSlots[] = {
    {"baseColor", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Base colour texture"), &Material::baseColorTexture, true},
    {"metallicRoughness", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Metallic-roughness texture"), &Material::metallicRoughnessTexture, false},
    {"normal", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Normal texture"), &Material::normalTexture, false},
    {"occlusion", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Occlusion texture"), &Material::occlusionTexture, false},
    {"emissive", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Emission texture"), &Material::emissiveTexture, true},
    {"specular", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Specular texture"), &Material::specularTexture, false},
    {"specularColor", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Specular colour texture"), &Material::specularColorTexture, true},
    {"transmission", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Transmission texture"), &Material::transmissionTexture, false},
    {"thickness", QT_TRANSLATE_NOOP("glint::editor::PropertyForm", "Thickness texture"), &Material::thicknessTexture, false},
};

bool startsWith(const QByteArray& bytes, std::initializer_list<unsigned char> magic) {
    if (bytes.size() < qsizetype(magic.size())) return false;
    return std::equal(magic.begin(), magic.end(), reinterpret_cast<const unsigned char*>(bytes.constData()));
}

// An image URI (a file name beside the scene) that no image of the scene uses: "brick.png", else
// "brick-1.png", "brick-2.png", ...
std::string uniqueImageUri(const Scene& scene, const std::string& stem, const std::string& suffix) {
    std::set<std::string> taken;
    for (const auto& [id, image] : scene.images) taken.insert(image.uri);
    std::string uri = stem + "." + suffix;
    for (int i = 1; taken.count(uri); ++i) uri = stem + "-" + std::to_string(i) + "." + suffix;
    return uri;
}

// File names glTF tools take everywhere: letters, digits, '-', '_' and '.'; the rest become '_'.
std::string plainStem(const QString& baseName) {
    std::string stem = baseName.toStdString();
    for (char& c : stem)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) c = '_';
    return stem.empty() ? std::string("texture") : stem;
}

struct EncodedTexture {
    std::vector<std::uint8_t> bytes;
    std::string mimeType;
    std::string suffix;
};

// The file as glTF can hold it: PNG and JPEG as they are, other formats as 8-bit PNG through
// OpenImageIO (linear to sRGB for colour slots). Throws a message naming the file.
EncodedTexture encodeForGltf(const QString& path, const QByteArray& bytes, bool color) {
    const QString name = QFileInfo(path).fileName();
    // Glint's limits on the header before OpenImageIO opens the file, and on the opened spec before
    // a pixel is read: an image bomb is refused, not allocated (docs/RELIABILITY.md).
    const auto refuse = [&](const std::string& why) {
        throw std::runtime_error(tr("%1 cannot be read as an image: %2").arg(name, QString::fromStdString(why)).toStdString());
    };
    const std::span<const std::uint8_t> raw(reinterpret_cast<const std::uint8_t*>(bytes.constData()), std::size_t(bytes.size()));
    if (const std::string why = headerLimitError(raw, raw.size(), 4, sizeof(float), DecodeLimits{}); !why.empty()) refuse(why);
    BoundedMemReader reader(bytes.constData(), std::size_t(bytes.size()));
    // OpenImageIO picks its reader by the file's extension; the bytes decide whether it reads.
    OIIO::ImageBuf image(path.toStdString(), 0, 0, nullptr, nullptr, &reader);
    if (image.spec().width > 0)
        if (const std::string why = openedLimitError(image.spec(), 4, sizeof(float), DecodeLimits{}); !why.empty()) refuse(why);
    if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT) || image.spec().width <= 0 || image.spec().height <= 0) {
        std::string why = image.geterror();
        if (why.empty()) why = "not an image OpenImageIO can read";
        throw std::runtime_error(tr("%1 cannot be read as an image: %2").arg(name, QString::fromStdString(why)).toStdString());
    }
    EncodedTexture out;
    if (startsWith(bytes, {0x89, 'P', 'N', 'G'}) || startsWith(bytes, {0xFF, 0xD8, 0xFF})) {
        const bool png = startsWith(bytes, {0x89, 'P', 'N', 'G'});
        out.bytes.assign(bytes.begin(), bytes.end());
        out.mimeType = png ? "image/png" : "image/jpeg";
        out.suffix = png ? "png" : "jpg";
        return out;
    }
    OIIO::ImageBuf converted = image;
    if (color) converted = OIIO::ImageBufAlgo::colorconvert(image, "linear", "sRGB");
    if (converted.has_error())
        throw std::runtime_error(tr("%1 cannot be converted: %2").arg(name, QString::fromStdString(converted.geterror())).toStdString());
    std::vector<unsigned char> png;
    OIIO::Filesystem::IOVecOutput writer(png);
    converted.set_write_format(OIIO::TypeDesc::UINT8);
    converted.set_write_ioproxy(&writer);
    if (!converted.write("texture.png", OIIO::TypeDesc::UINT8, "png"))
        throw std::runtime_error(tr("%1 cannot be converted to PNG: %2").arg(name, QString::fromStdString(converted.geterror())).toStdString());
    out.bytes.assign(png.begin(), png.end());
    out.mimeType = "image/png";
    out.suffix = "png";
    return out;
}

} // namespace

std::vector<NodeId> materialUsers(const Scene& scene, MaterialId material) {
    std::vector<NodeId> users;
    if (!material) return users;
    for (const auto& [id, node] : scene.nodes()) {
        if (const auto* shape = node.get<Shape>()) {
            if (shape->material == material) users.push_back(id);
        } else if (const auto* instance = node.get<MeshInstance>()) {
            const Mesh* mesh = scene.meshes.find(instance->mesh);
            if (mesh && std::any_of(mesh->primitives.begin(), mesh->primitives.end(),
                                    [&](const Primitive& p) { return p.material == material; }))
                users.push_back(id);
        }
    }
    return users;
}

std::string uniqueMaterialName(const Scene& scene, const std::string& base) {
    const auto taken = [&](const std::string& name) {
        return std::any_of(scene.materials.begin(), scene.materials.end(), [&](const auto& e) { return e.second.name == name; });
    };
    if (!taken(base)) return base;
    std::string stem = base;
    const std::size_t dot = base.rfind('.');
    if (dot != std::string::npos && base.size() - dot - 1 == 3 &&
        std::all_of(base.begin() + std::ptrdiff_t(dot) + 1, base.end(), [](char c) { return c >= '0' && c <= '9'; }))
        stem = base.substr(0, dot);
    for (int i = 1;; ++i) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, ".%03d", i);
        if (!taken(stem + suffix)) return stem + suffix;
    }
}

QString newMaterial(Document& document, Material value, MaterialId* added) {
    value.name = uniqueMaterialName(document.scene(), value.name.empty() ? std::string("Material") : value.name);
    MaterialId id;
    try {
        id = pushMaterial(document, std::move(value));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    if (added) *added = id;
    return {};
}

QString duplicateMaterial(Document& document, MaterialId material, MaterialId* added) {
    const Material* source = document.scene().materials.find(material);
    if (!source) return tr("The material no longer exists.");
    Material copy = *source;
    copy.name = uniqueMaterialName(document.scene(), source->name.empty() ? std::string("Material") : source->name);
    MaterialId id;
    try {
        auto command = std::make_unique<AddAsset<Material>>(std::move(copy));
        AddAsset<Material>* raw = command.get();
        document.push(withLabel(std::move(command), "Duplicate material"));
        id = raw->id();
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    if (added) *added = id;
    return {};
}

QString renameMaterial(Document& document, MaterialId material, const QString& name) {
    const Material* m = document.scene().materials.find(material);
    if (!m) return tr("The material no longer exists.");
    const std::string wanted = name.trimmed().toStdString();
    if (wanted.empty()) return tr("A material needs a name.");
    if (wanted == m->name) return {};
    Material renamed = *m;
    renamed.name = uniqueMaterialName(document.scene(), wanted);
    return pushOne(document, withLabel(std::make_unique<SetMaterial>(material, std::move(renamed)), "Rename material"));
}

QString deleteUnusedMaterials(Document& document, int* removed) {
    std::vector<MaterialId> unused;
    for (const auto& [id, material] : document.scene().materials)
        if (!isInUse(document.scene(), id)) unused.push_back(id);
    if (removed) *removed = int(unused.size());
    if (unused.empty()) return {};
    return inMacro(document, tr("Delete unused materials"), [&] {
        for (const MaterialId id : unused) document.push(std::make_unique<RemoveAsset<Material>>(id));
    });
}

QString assignMaterial(Document& document, MaterialId material, const std::vector<NodeId>& nodes) {
    const Scene& scene = document.scene();
    if (material && !scene.materials.contains(material)) return tr("The material no longer exists.");
    std::vector<CommandPtr> commands;
    std::set<MeshId> meshes; // a mesh shared by several selected nodes changes once
    for (const NodeId id : nodes) {
        const Node* node = scene.node(id);
        if (!node) continue;
        if (const auto* shape = node->get<Shape>()) {
            if (shape->material == material) continue;
            Shape changed = *shape;
            changed.material = material;
            commands.push_back(withLabel(std::make_unique<SetComponent>(id, changed), "Assign material"));
        } else if (const auto* instance = node->get<MeshInstance>()) {
            const Mesh* mesh = scene.meshes.find(instance->mesh);
            if (!mesh || !meshes.insert(instance->mesh).second) continue;
            for (std::size_t p = 0; p < mesh->primitives.size(); ++p)
                if (mesh->primitives[p].material != material)
                    commands.push_back(std::make_unique<SetPrimitiveMaterial>(instance->mesh, p, material));
        }
    }
    const bool anyTarget = std::any_of(nodes.begin(), nodes.end(), [&](NodeId id) {
        const Node* n = scene.node(id);
        return n && (n->get<Shape>() || n->get<MeshInstance>());
    });
    if (!anyTarget) return tr("Select a shape or a mesh to assign the material to.");
    if (commands.empty()) return {}; // they all use it already
    if (commands.size() == 1) return pushOne(document, std::move(commands.front()));
    return inMacro(document, tr("Assign material"), [&] {
        for (CommandPtr& command : commands) document.push(std::move(command));
    });
}

QString assignPrimitiveMaterial(Document& document, MeshId mesh, std::size_t primitive, MaterialId material) {
    const Mesh* m = document.scene().meshes.find(mesh);
    if (!m || primitive >= m->primitives.size()) return tr("The mesh no longer exists.");
    if (m->primitives[primitive].material == material) return {};
    return pushOne(document, std::make_unique<SetPrimitiveMaterial>(mesh, primitive, material));
}

QMimeData* encodeMaterials(const std::vector<MaterialId>& materials) {
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    QList<quint32> ids;
    for (const MaterialId id : materials) ids << id.value;
    out << ids;
    auto* data = new QMimeData;
    data->setData(kMaterialMimeType, bytes);
    return data;
}

std::vector<MaterialId> decodeMaterials(const QMimeData* data) {
    std::vector<MaterialId> materials;
    if (!data || !data->hasFormat(kMaterialMimeType)) return materials;
    QByteArray bytes = data->data(kMaterialMimeType);
    QDataStream in(&bytes, QIODevice::ReadOnly);
    QList<quint32> ids;
    in >> ids;
    for (const quint32 id : ids) materials.push_back(MaterialId{id});
    return materials;
}

bool takesMaterial(const Scene& scene, NodeId node) {
    const Node* n = scene.node(node);
    return n && (n->get<Shape>() || n->get<MeshInstance>());
}

std::span<const TextureSlot> textureSlots() { return kSlots; }

const TextureSlot* findTextureSlot(const QString& id) {
    for (const TextureSlot& slot : kSlots)
        if (id == QLatin1String(slot.id)) return &slot;
    return nullptr;
}

QString loadTextureFile(Document& document, MaterialId material, const TextureSlot& slot, const QString& path) {
    const Material* m = document.scene().materials.find(material);
    if (!m) return tr("The material no longer exists.");
    const QFileInfo info(path);
    QFile file(path);
    if (!info.isFile()) return tr("%1 does not exist.").arg(path);
    if (!file.open(QIODevice::ReadOnly)) return tr("%1 cannot be read: %2").arg(path, file.errorString());
    const QByteArray bytes = file.readAll();
    if (bytes.isEmpty()) return tr("%1 is empty.").arg(path);
    EncodedTexture encoded;
    try {
        encoded = encodeForGltf(path, bytes, slot.color);
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    const Scene& scene = document.scene();
    Image image;
    image.name = info.completeBaseName().toStdString();
    image.uri = uniqueImageUri(scene, plainStem(info.completeBaseName()), encoded.suffix);
    image.mimeType = encoded.mimeType;
    if (const auto size = probeImageHeader(encoded.bytes)) {
        image.width = size->width;
        image.height = size->height;
    }
    image.encoded = std::move(encoded.bytes);
    Sampler sampler;
    sampler.magFilter = Filter::Linear;
    sampler.minFilter = Filter::LinearMipmapLinear;
    return inMacro(document, tr("Load texture %1").arg(info.fileName()), [&] {
        const ImageId imageId = pushAsset(document, std::move(image));
        const SamplerId samplerId = pushAsset(document, sampler);
        Texture texture;
        texture.name = info.completeBaseName().toStdString();
        texture.image = imageId;
        texture.sampler = samplerId;
        const TextureId textureId = pushAsset(document, std::move(texture));
        Material changed = document.scene().materials.at(material);
        (changed.*slot.member).texture = textureId;
        document.push(withLabel(std::make_unique<SetMaterial>(material, std::move(changed)), "Change texture"));
    });
}

} // namespace glint::editor
