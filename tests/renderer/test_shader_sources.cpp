// Shader sources without a GL context: the include resolver, compiler-log mapping, the embedded
// table, and a lint that keeps the renderer inside OpenGL 4.1 (macOS's ceiling).
#include "gl41_lint_patterns.h"
#include "renderer/gl/include_resolver.h"
#include "shaders/embedded_shaders.h"

#include <QTest>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using namespace glint;
using glint::test::forbiddenGlCall;
using glint::test::versionDirective;

namespace {

gl::ShaderLookup lookupIn(const std::map<std::string, std::string>& files) {
    return [&files](std::string_view name) -> std::optional<std::string_view> {
        const auto it = files.find(std::string(name));
        if (it == files.end()) return std::nullopt;
        return std::string_view(it->second);
    };
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::filesystem::path sourceRoot = std::filesystem::path(GLINT_TEST_DATA_DIR) / ".." / "..";

} // namespace

class TestShaderSources : public QObject {
    Q_OBJECT
private slots:
    void includesResolveOnceEach() {
        const std::map<std::string, std::string> files{
            {"main.glsl", "#include \"a.glsl\"\n#include \"b.glsl\"\nvoid main() {}\n"},
            {"a.glsl", "#include \"common/c.glsl\"\nfloat a;\n"},
            {"b.glsl", "  #include \"common/c.glsl\"\nfloat b;\n"},
            {"common/c.glsl", "float c;\n"}};
        const auto resolved = gl::resolveIncludes("main.glsl", "#version 410 core", "#define X 1\n", lookupIn(files));
        QCOMPARE(resolved.files, (std::vector<std::string>{"<prelude>", "main.glsl", "a.glsl", "common/c.glsl", "b.glsl"}));
        QCOMPARE(QString::fromStdString(resolved.text),
                 QString("#version 410 core\n#line 1 0\n#define X 1\n#line 1 1\n#line 1 2\n#line 1 3\nfloat c;\n"
                         "#line 2 2\nfloat a;\n#line 2 1\n#line 1 4\n#line 2 4\nfloat b;\n#line 3 1\nvoid main() {}\n"));
    }

    void includeNextToTheIncluderWinsOverTheRoot() {
        const std::map<std::string, std::string> files{
            {"pass/main.glsl", "#include \"util.glsl\"\n"}, {"pass/util.glsl", "float near;\n"}, {"util.glsl", "float root;\n"}};
        const auto resolved = gl::resolveIncludes("pass/main.glsl", "#version 410 core", "", lookupIn(files));
        QVERIFY(resolved.text.find("float near;") != std::string::npos);
        QVERIFY(resolved.text.find("float root;") == std::string::npos);
    }

    void missingIncludeNamesFileAndLine() {
        const std::map<std::string, std::string> files{{"main.glsl", "float x;\n#include \"gone.glsl\"\n"}};
        try {
            gl::resolveIncludes("main.glsl", "#version 410 core", "", lookupIn(files));
            QFAIL("no exception");
        } catch (const std::runtime_error& e) {
            QCOMPARE(QString(e.what()), QString("main.glsl:2: cannot find #include \"gone.glsl\""));
        }
    }

    void compilerLogsMapToFiles() {
        const std::vector<std::string> files{"<prelude>", "pathtrace/main.frag.glsl", "pathtrace/shapes.glsl"};
        QCOMPARE(QString::fromStdString(gl::mapLogToFiles("2:14(7): error: `foo' undeclared\n1:3(1): warning: x\n", files)),
                 QString("pathtrace/shapes.glsl:14: error: `foo' undeclared\npathtrace/main.frag.glsl:3: warning: x\n"));
        QCOMPARE(QString::fromStdString(gl::mapLogToFiles("2(14) : error C1008: undefined variable", files)),
                 QString("pathtrace/shapes.glsl:14: error C1008: undefined variable"));
    }

    // Every file under shaders/ is embedded, under its relative path, sorted, with its exact text.
    void everyShaderIsEmbedded() {
        std::vector<std::string> onDisk;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(sourceRoot / "shaders"))
            if (entry.path().extension() == ".glsl")
                onDisk.push_back(std::filesystem::relative(entry.path(), sourceRoot / "shaders").generic_string());
        std::sort(onDisk.begin(), onDisk.end());
        std::vector<std::string> embedded;
        for (const auto& shader : shaders::all()) embedded.emplace_back(shader.name);
        QCOMPARE(embedded, onDisk);
        for (const auto& name : onDisk)
            QCOMPARE(std::string(*shaders::find(name)), readFile(sourceRoot / "shaders" / name));
        QVERIFY(!shaders::find("no/such.glsl"));
    }

    // No GL 4.2+ entry point in renderer/ and shaders/, and no #version but 410 core.
    void staysInsideOpenGl41() {
        int scanned = 0;
        for (const char* folder : {"renderer", "shaders"}) {
            for (const auto& entry : std::filesystem::recursive_directory_iterator(sourceRoot / folder)) {
                const auto ext = entry.path().extension();
                if (ext != ".cpp" && ext != ".h" && ext != ".glsl") continue;
                ++scanned;
                const std::string text = readFile(entry.path());
                std::smatch m;
                QVERIFY2(!std::regex_search(text, m, forbiddenGlCall()),
                         qPrintable(QString::fromStdString(entry.path().string() + ": GL 4.2+ call " + m.str(0))));
                for (std::sregex_iterator it(text.begin(), text.end(), versionDirective()), end; it != end; ++it)
                    QVERIFY2(it->str(0).find("410 core") != std::string::npos,
                             qPrintable(QString::fromStdString(entry.path().string() + ": " + it->str(0))));
            }
        }
        QVERIFY(scanned > 20);
    }
};

QTEST_APPLESS_MAIN(TestShaderSources)
#include "test_shader_sources.moc"
