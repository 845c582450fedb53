// The project file <basename>.glint.json (docs/FILE_FORMAT.md): parsed strictly (a wrong type is an
// error naming the key), unknown keys kept with a warning, older schemas migrated step by step.
#include "project_file.h"

#include "scene/io/files/confined_path.h"
#include "scene/io/json/json_numbers.h"
#include "scene/io/json/json_parse.h"

#include <array>
#include <cmath>
#include <exception>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace glint {

namespace {

using nlohmann::json;

constexpr int kMaxJsonDepth = 64;

// kMigrations[v - 1] turns schema v into schema v + 1. Schema 1 is the first: none yet. A new schema
// adds its step here, so every older file still opens.
using Migration = void (*)(json&);
constexpr std::array<Migration, kProjectSchemaVersion - 1> kMigrations{};

// Reads the members of one JSON object; what it was never asked for is unknown.
class ObjectReader {
public:
    ObjectReader(const json& object, std::string prefix, const std::string& file, Warnings& warnings, json& unknown)
        : object_(object), prefix_(std::move(prefix)), file_(file), warnings_(warnings), unknown_(unknown) {}

    ~ObjectReader()
    {
        if (std::uncaught_exceptions() > 0) return;
        for (const auto& [key, value] : object_.items()) {
            if (asked_.count(key)) continue;
            unknown_[key] = value;
            warnings_.push_back({file_, "unknown-key", "unknown key '" + prefix_ + key + "' kept as it is"});
        }
    }

    const json* find(const std::string& key)
    {
        asked_.insert(key);
        auto it = object_.find(key);
        return it == object_.end() ? nullptr : &*it;
    }

    [[noreturn]] void wrongType(const std::string& key, const std::string& expected) const
    {
        throw FileError(file_, "wrong-type", "key '" + prefix_ + key + "' must be " + expected);
    }

    void read(const std::string& key, std::string& out)
    {
        const json* v = find(key);
        if (!v) return;
        if (!v->is_string()) wrongType(key, "a string");
        out = v->get<std::string>();
    }
    void read(const std::string& key, int& out)
    {
        const json* v = find(key);
        if (!v) return;
        if (!v->is_number_integer() || *v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max())
            wrongType(key, "an integer");
        out = v->get<int>();
    }
    void read(const std::string& key, std::uint32_t& out)
    {
        const json* v = find(key);
        if (!v) return;
        if (!v->is_number_integer() || *v < 0 || *v > std::numeric_limits<std::uint32_t>::max())
            wrongType(key, "an integer from 0 to 4294967295");
        out = v->get<std::uint32_t>();
    }
    void read(const std::string& key, bool& out)
    {
        const json* v = find(key);
        if (!v) return;
        if (!v->is_boolean()) wrongType(key, "true or false");
        out = v->get<bool>();
    }
    // A value that must also pass `valid`; `expected` names the allowed range in the error.
    template <class T, class Valid>
    void readChecked(const std::string& key, T& out, Valid valid, const std::string& expected)
    {
        T value = out;
        read(key, value);
        if (!valid(value)) throw FileError(file_, "bad-value", "key '" + prefix_ + key + "' must be " + expected);
        out = value;
    }
    void read(const std::string& key, float& out)
    {
        const json* v = find(key);
        if (!v) return;
        if (!v->is_number()) wrongType(key, "a number");
        out = v->get<float>();
    }
    void read(const std::string& key, double& out)
    {
        const json* v = find(key);
        if (!v) return;
        if (!v->is_number()) wrongType(key, "a number");
        out = v->get<double>();
    }
    void read(const std::string& key, glm::vec3& out)
    {
        const json* v = find(key);
        if (!v) return;
        if (!v->is_array() || v->size() != 3 || !(*v)[0].is_number() || !(*v)[1].is_number() || !(*v)[2].is_number())
            wrongType(key, "an array of 3 numbers");
        out = {(*v)[0].get<float>(), (*v)[1].get<float>(), (*v)[2].get<float>()};
    }

    // A nested object: its reader collects its own unknown keys under unknown[key].
    template <class Fn>
    void object(const std::string& key, Fn&& readMembers)
    {
        const json* v = find(key);
        if (!v) return;
        if (!v->is_object()) wrongType(key, "an object");
        json nestedUnknown = json::object();
        {
            ObjectReader nested(*v, prefix_ + key + ".", file_, warnings_, nestedUnknown);
            readMembers(nested);
        }
        if (!nestedUnknown.empty()) unknown_[key] = std::move(nestedUnknown);
    }

    template <class Enum, std::size_t N>
    void readEnum(const std::string& key, Enum& out, const std::array<std::pair<const char*, Enum>, N>& names)
    {
        std::string text;
        read(key, text);
        if (!find(key)) return;
        std::string allowed;
        for (const auto& [name, value] : names) {
            if (text == name) {
                out = value;
                return;
            }
            allowed += (allowed.empty() ? "" : ", ") + std::string(name);
        }
        throw FileError(file_, "bad-value", "key '" + prefix_ + key + "' must be one of " + allowed + ", not '" + text + "'");
    }

    const std::string& file() const { return file_; }

private:
    const json& object_;
    std::string prefix_;
    const std::string& file_;
    Warnings& warnings_;
    json& unknown_;
    std::set<std::string> asked_;
};

constexpr std::array<std::pair<const char*, LightUnits>, 2> kLightUnitNames{{{"blender", LightUnits::Blender}, {"raw", LightUnits::Raw}}};
constexpr std::array<std::pair<const char*, Tonemapper>, 6> kTonemapperNames{
    {{"none", Tonemapper::None}, {"aces", Tonemapper::AcesFitted}, {"pbrNeutral", Tonemapper::PbrNeutral},
     {"agx", Tonemapper::AgX}, {"reinhard", Tonemapper::Reinhard}, {"hable", Tonemapper::Hable}}};

constexpr std::array<std::pair<const char*, TaaClip>, 3> kTaaClipNames{
    {{"variance", TaaClip::Variance}, {"minmax", TaaClip::MinMax}, {"none", TaaClip::None}}};

template <class Enum, std::size_t N>
const char* enumName(Enum value, const std::array<std::pair<const char*, Enum>, N>& names)
{
    for (const auto& [name, v] : names)
        if (v == value) return name;
    return names.front().first;
}

// Ranges outside which the filters divide by zero, never converge or stop filtering at all.
bool inUnitInterval(float v) { return v > 0.0f && v <= 1.0f; }

void readTaa(ObjectReader& r, TaaParameters& t)
{
    r.readChecked("blend", t.blend, inUnitInterval, "greater than 0 and at most 1");
    r.readEnum("clip", t.clip, kTaaClipNames);
    r.readChecked("clipGamma", t.clipGamma, [](float v) { return v > 0.0f && v <= 16.0f; }, "greater than 0 and at most 16");
    r.read("perceptualBlend", t.perceptualBlend);
}

void readSvgf(ObjectReader& r, SvgfParameters& s)
{
    r.readChecked("iterations", s.iterations, [](int v) { return v >= 1 && v <= 10; }, "an integer from 1 to 10");
    r.readChecked("alpha", s.alpha, inUnitInterval, "greater than 0 and at most 1");
    r.readChecked("momentsAlpha", s.momentsAlpha, inUnitInterval, "greater than 0 and at most 1");
    const auto positive = [](float v) { return v > 0.0f && v <= std::numeric_limits<float>::max(); };
    r.readChecked("sigmaLuminance", s.sigmaLuminance, positive, "a positive number");
    r.readChecked("sigmaNormal", s.sigmaNormal, [](float v) { return v >= 0.0f && v <= std::numeric_limits<float>::max(); },
                  "a number of at least 0");
    r.readChecked("sigmaDepth", s.sigmaDepth, positive, "a positive number");
    r.readChecked("fireflyRatio", s.fireflyRatio, [](float v) { return v >= 1.0f && v <= std::numeric_limits<float>::max(); },
                  "a number of at least 1");
}

// The command line's ranges (--size, --spp, --bounces), so a project renders whatever it says and
// a value the CLI would refuse is refused at load, naming the file and the key.
bool inRange(int v, int low, int high) { return v >= low && v <= high; }
bool finiteFloat(float v) { return std::isfinite(v); }
bool nonNegativeFinite(float v) { return std::isfinite(v) && v >= 0.0f; }

void readBloom(ObjectReader& r, BloomParameters& b)
{
    r.readChecked("strength", b.strength, [](float v) { return v >= 0.0f && v <= 1.0f; }, "a number from 0 (off) to 1");
    r.readChecked("radius", b.radius, [](float v) { return v > 0.0f && v <= 1.0f; },
                  "a fraction of the image height above 0, at most 1");
}

constexpr std::array<std::pair<const char*, AdaptiveGoal>, 2> kAdaptiveGoalNames{
    {{adaptiveGoalName(AdaptiveGoal::Even), AdaptiveGoal::Even}, {adaptiveGoalName(AdaptiveGoal::Mean), AdaptiveGoal::Mean}}};

void readAdaptive(ObjectReader& r, AdaptiveSampling& a)
{
    r.readEnum("goal", a.goal, kAdaptiveGoalNames);
    r.readChecked("threshold", a.threshold, [](float v) { return v >= 0.0f && v <= 1.0f; }, "a number from 0 (off) to 1");
    r.readChecked("minSpp", a.minSamples, [](int v) { return inRange(v, 0, kMaxProjectSpp); },
                  "an integer from 0 (automatic) to " + std::to_string(kMaxProjectSpp));
}

void readRender(ObjectReader& r, RenderSettings& s)
{
    r.read("configuration", s.configuration);
    const auto size = [](int v) { return inRange(v, 1, kMaxProjectImageSize); };
    const std::string sizeText = "an integer from 1 to " + std::to_string(kMaxProjectImageSize);
    r.readChecked("width", s.width, size, sizeText);
    r.readChecked("height", s.height, size, sizeText);
    r.readChecked("spp", s.spp, [](int v) { return inRange(v, 1, kMaxProjectSpp); },
                  "an integer from 1 to " + std::to_string(kMaxProjectSpp));
    r.readChecked("bounces", s.bounces, [](int v) { return inRange(v, 0, kMaxProjectBounces); },
                  "an integer from 0 to " + std::to_string(kMaxProjectBounces));
    r.read("seed", s.seed);
    r.readChecked("exposure", s.exposure, [](float v) { return std::abs(v) <= kMaxProjectExposureEv; },
                  "a number of stops from -" + std::to_string(int(kMaxProjectExposureEv)) + " to " +
                      std::to_string(int(kMaxProjectExposureEv)));
    r.readEnum("tonemapper", s.tonemapper, kTonemapperNames);
    r.readChecked("clamp", s.clamp, nonNegativeFinite, "0 (off) or a positive number");
    r.readChecked("shutter", s.shutter, [](float v) { return v >= 0.0f && v <= 1.0f; }, "a fraction of a frame from 0 (off) to 1");
    r.readChecked("sampleBlock", s.sampleBlock, isSampleBlock, "1 (off), 2, 4 or 8");
    r.object("taa", [&](ObjectReader& nested) { readTaa(nested, s.taa); });
    r.object("svgf", [&](ObjectReader& nested) { readSvgf(nested, s.svgf); });
    r.object("bloom", [&](ObjectReader& nested) { readBloom(nested, s.bloom); });
    r.object("adaptive", [&](ObjectReader& nested) { readAdaptive(nested, s.adaptive); });
}

void readEnvironment(ObjectReader& r, Environment& e)
{
    r.read("file", e.file);
    r.readChecked("color", e.color, [](const glm::vec3& c) { return nonNegativeFinite(c.x) && nonNegativeFinite(c.y) && nonNegativeFinite(c.z); },
                  "3 numbers of at least 0");
    r.readChecked("intensity", e.intensity, nonNegativeFinite, "a number of at least 0");
    r.readChecked("rotation", e.rotationDegrees, finiteFloat, "a finite number of degrees");
}

// The ranges the renderer's medium is defined on (docs/MEDIA.md): a negative density or falloff
// would add light; |g| = 1 makes the Henyey-Greenstein lobe a delta its sampling cannot take.
bool unitColor(const glm::vec3& c)
{
    const auto unit = [](float v) { return v >= 0.0f && v <= 1.0f; };
    return unit(c.x) && unit(c.y) && unit(c.z);
}

void readFog(ObjectReader& r, Fog& f)
{
    r.readChecked("density", f.density, nonNegativeFinite, "a number of at least 0 (per metre)");
    r.readChecked("color", f.color, unitColor, "3 numbers from 0 to 1");
    r.readChecked("anisotropy", f.anisotropy, [](float v) { return v >= -kMaxFogAnisotropy && v <= kMaxFogAnisotropy; },
                  "a number from -0.99 to 0.99");
    r.readChecked("heightFalloff", f.heightFalloff, nonNegativeFinite, "a number of at least 0 (per metre)");
    r.readChecked("baseHeight", f.baseHeight, finiteFloat, "a finite number of metres");
}

void readTimeline(ObjectReader& r, Timeline& t)
{
    r.read("start", t.start);
    r.read("end", t.end);
    const json* fps = r.find("fps");
    if (!fps) return;
    const bool valid = fps->is_array() && fps->size() == 2 && (*fps)[0].is_number_integer() &&
                       (*fps)[1].is_number_integer() && (*fps)[0] > 0 && (*fps)[1] > 0 &&
                       (*fps)[0] <= std::numeric_limits<int>::max() && (*fps)[1] <= std::numeric_limits<int>::max();
    if (!valid) r.wrongType("fps", "[numerator, denominator] with positive integers");
    t.fpsNumerator = (*fps)[0].get<int>();
    t.fpsDenominator = (*fps)[1].get<int>();
}

void readOutput(ObjectReader& r, OutputSettings& o)
{
    r.read("path", o.path);
    r.read("aovs", o.aovs);
    r.read("passes", o.passes);
    r.read("codec", o.codec);
}

void readProject(ObjectReader& r, ProjectFile& project)
{
    ProjectSettings& s = project.settings;
    r.find("glint"); // checked by migrate()
    r.read("scene", project.sceneFile);
    std::uint32_t camera = 0;
    r.read("activeCamera", camera);
    s.activeCamera = NodeId{camera};
    r.readEnum("lightUnits", s.lightUnits, kLightUnitNames);
    r.object("render", [&](ObjectReader& nested) { readRender(nested, s.render); });
    r.object("environment", [&](ObjectReader& nested) { readEnvironment(nested, s.environment); });
    r.object("fog", [&](ObjectReader& nested) { readFog(nested, s.fog); });
    r.object("timeline", [&](ObjectReader& nested) { readTimeline(nested, s.timeline); });
    r.object("output", [&](ObjectReader& nested) { readOutput(nested, s.output); });
}

void migrate(json& root, const std::string& file)
{
    auto version = root.find("glint");
    if (version == root.end())
        throw FileError(file, "not-a-project", "not a Glint project file: the schema version 'glint' is missing");
    if (!version->is_number_integer()) throw FileError(file, "wrong-type", "key 'glint' must be an integer");
    const auto from = version->get<std::int64_t>();
    if (from > kProjectSchemaVersion)
        throw FileError(file, "newer-version", "written by a newer Glint (project schema " + std::to_string(from) +
                                                   "; this Glint reads up to " + std::to_string(kProjectSchemaVersion) + ")");
    if (from < 1) throw FileError(file, "bad-version", "project schema " + std::to_string(from) + " does not exist");
    for (auto v = from; v < kProjectSchemaVersion; ++v) kMigrations[static_cast<std::size_t>(v - 1)](root);
    root["glint"] = kProjectSchemaVersion;
}

// Only what differs from the defaults, so files that never touched these stay byte-identical.
json taaJson(const TaaParameters& t)
{
    const TaaParameters d;
    json j = json::object();
    if (t.blend != d.blend) j["blend"] = jsonFloat(t.blend);
    if (t.clip != d.clip) j["clip"] = enumName(t.clip, kTaaClipNames);
    if (t.clipGamma != d.clipGamma) j["clipGamma"] = jsonFloat(t.clipGamma);
    if (t.perceptualBlend != d.perceptualBlend) j["perceptualBlend"] = t.perceptualBlend;
    return j;
}

json bloomJson(const BloomParameters& b)
{
    const BloomParameters d;
    json j = json::object();
    if (b.strength != d.strength) j["strength"] = jsonFloat(b.strength);
    if (b.radius != d.radius) j["radius"] = jsonFloat(b.radius);
    return j;
}

json adaptiveJson(const AdaptiveSampling& a)
{
    const AdaptiveSampling d;
    json j = json::object();
    if (a.threshold != d.threshold) j["threshold"] = jsonFloat(a.threshold);
    if (a.minSamples != d.minSamples) j["minSpp"] = a.minSamples;
    if (a.goal != d.goal) j["goal"] = enumName(a.goal, kAdaptiveGoalNames);
    return j;
}

json svgfJson(const SvgfParameters& s)
{
    const SvgfParameters d;
    json j = json::object();
    if (s.iterations != d.iterations) j["iterations"] = s.iterations;
    if (s.alpha != d.alpha) j["alpha"] = jsonFloat(s.alpha);
    if (s.momentsAlpha != d.momentsAlpha) j["momentsAlpha"] = jsonFloat(s.momentsAlpha);
    if (s.sigmaLuminance != d.sigmaLuminance) j["sigmaLuminance"] = jsonFloat(s.sigmaLuminance);
    if (s.sigmaNormal != d.sigmaNormal) j["sigmaNormal"] = jsonFloat(s.sigmaNormal);
    if (s.sigmaDepth != d.sigmaDepth) j["sigmaDepth"] = jsonFloat(s.sigmaDepth);
    if (s.fireflyRatio != d.fireflyRatio) j["fireflyRatio"] = jsonFloat(s.fireflyRatio);
    return j;
}

// Written only for a fog, so projects without one keep their bytes; then all five values, so the
// file says what the fog is without the reader's defaults.
json fogJson(const Fog& f)
{
    return {{"density", jsonFloat(f.density)},
            {"color", {jsonFloat(f.color.x), jsonFloat(f.color.y), jsonFloat(f.color.z)}},
            {"anisotropy", jsonFloat(f.anisotropy)},
            {"heightFalloff", jsonFloat(f.heightFalloff)},
            {"baseHeight", jsonFloat(f.baseHeight)}};
}

} // namespace

std::filesystem::path projectPathFor(const std::filesystem::path& sceneFile)
{
    std::filesystem::path project = sceneFile;
    project.replace_extension(".glint.json");
    return project;
}

bool isProjectPath(const std::filesystem::path& file)
{
    const std::string name = file.filename().string();
    const std::string suffix = ".glint.json";
    return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

ProjectFile parseProjectFile(const std::string& text, const std::string& displayName, Warnings& warnings)
{
    json root = parseJsonText(text, displayName, kMaxJsonDepth);
    if (!root.is_object()) throw FileError(displayName, "wrong-type", "a project file must be a JSON object");
    migrate(root, displayName);
    ProjectFile project;
    project.settings.unknown = json::object();
    {
        ObjectReader reader(root, "", displayName, warnings, project.settings.unknown);
        readProject(reader, project);
    }
    if (project.settings.unknown.empty()) project.settings.unknown = nullptr;
    return project;
}

ProjectFile readProjectFile(const std::filesystem::path& file, Warnings& warnings)
{
    std::ifstream in(file, std::ios::binary);
    if (!in) throw FileError(file.string(), "cannot-open", "cannot open the project file");
    std::ostringstream text;
    text << in.rdbuf();
    ProjectFile project = parseProjectFile(text.str(), file.string(), warnings);
    if (const std::string& env = project.settings.environment.file; !env.empty())
        projectEnvironmentPath(file.parent_path(), env, file.string());
    return project;
}

std::filesystem::path projectEnvironmentPath(const std::filesystem::path& projectFolder, const std::string& file,
                                             const std::string& displayName)
{
    const ConfinedFolder folder{projectFolder.empty() ? std::filesystem::path(".") : projectFolder};
    if (auto problem = confinementProblem(folder, file))
        throw FileError(displayName, "uri-escapes-folder", "key 'environment.file': " + *problem);
    return folder.root / file;
}

std::string writeProjectFileText(const ProjectFile& project)
{
    const ProjectSettings& s = project.settings;
    json root{{"glint", kProjectSchemaVersion}, {"lightUnits", enumName(s.lightUnits, kLightUnitNames)}};
    if (!project.sceneFile.empty()) root["scene"] = project.sceneFile;
    if (s.activeCamera.valid()) root["activeCamera"] = s.activeCamera.value;
    const RenderSettings& r = s.render;
    root["render"] = {{"configuration", r.configuration}, {"width", r.width}, {"height", r.height}, {"spp", r.spp},
                      {"bounces", r.bounces}, {"seed", r.seed}, {"exposure", jsonFloat(r.exposure)},
                      {"tonemapper", enumName(r.tonemapper, kTonemapperNames)}, {"clamp", jsonFloat(r.clamp)}};
    if (r.shutter > 0.0f) root["render"]["shutter"] = jsonFloat(r.shutter); // files without motion blur keep their bytes
    if (r.sampleBlock != 1) root["render"]["sampleBlock"] = r.sampleBlock;  // likewise files without sample blocks
    if (json taa = taaJson(r.taa); !taa.empty()) root["render"]["taa"] = std::move(taa);
    if (json svgf = svgfJson(r.svgf); !svgf.empty()) root["render"]["svgf"] = std::move(svgf);
    if (json bloom = bloomJson(r.bloom); !bloom.empty()) root["render"]["bloom"] = std::move(bloom);
    if (json adaptive = adaptiveJson(r.adaptive); !adaptive.empty()) root["render"]["adaptive"] = std::move(adaptive);
    const Environment& e = s.environment;
    root["environment"] = {{"color", {jsonFloat(e.color.x), jsonFloat(e.color.y), jsonFloat(e.color.z)}},
                           {"intensity", jsonFloat(e.intensity)}, {"rotation", jsonFloat(e.rotationDegrees)}};
    if (!e.file.empty()) root["environment"]["file"] = e.file;
    if (s.fog != Fog{}) root["fog"] = fogJson(s.fog);
    const Timeline& t = s.timeline;
    root["timeline"] = {{"start", t.start}, {"end", t.end}, {"fps", {t.fpsNumerator, t.fpsDenominator}}};
    root["output"] = {{"path", s.output.path}, {"aovs", s.output.aovs}, {"codec", s.output.codec}};
    if (!s.output.passes.empty()) root["output"]["passes"] = s.output.passes; // left out when none: older files keep their bytes
    mergeUnknown(root, s.unknown);
    return deterministicJsonText(root, 2) + "\n";
}

} // namespace glint
