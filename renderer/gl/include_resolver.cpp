#include "renderer/gl/include_resolver.h"

#include <regex>
#include <set>
#include <stdexcept>

namespace glint::gl {
namespace {

constexpr int maxIncludeDepth = 32;

std::string folderOf(std::string_view file) {
    const auto slash = file.rfind('/');
    return slash == std::string_view::npos ? std::string() : std::string(file.substr(0, slash + 1));
}

// The quoted name of an `#include "name"` line, or nullopt if the line is no include directive.
std::optional<std::string> includedName(std::string_view line, std::string_view file, int lineNumber) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line.substr(first, 8) != "#include") return std::nullopt;
    const auto open = line.find('"', first + 8);
    const auto close = open == std::string_view::npos ? open : line.find('"', open + 1);
    if (close == std::string_view::npos)
        throw std::runtime_error(std::string(file) + ":" + std::to_string(lineNumber) + ": malformed #include");
    return std::string(line.substr(open + 1, close - open - 1));
}

class Resolver {
public:
    explicit Resolver(const ShaderLookup& lookup) : lookup_(lookup) {}

    void append(const std::string& file, std::string_view source, int depth) {
        if (depth > maxIncludeDepth) throw std::runtime_error(file + ": #include nested deeper than 32 levels");
        included_.insert(file);
        const int index = static_cast<int>(out_.files.size());
        out_.files.push_back(file);
        out_.text += "#line 1 " + std::to_string(index) + "\n";
        int lineNumber = 0;
        for (std::size_t begin = 0; begin < source.size();) {
            auto end = source.find('\n', begin);
            if (end == std::string_view::npos) end = source.size();
            const auto line = source.substr(begin, end - begin);
            ++lineNumber;
            begin = end + 1;
            const auto name = includedName(line, file, lineNumber);
            if (!name) {
                out_.text.append(line).append("\n");
                continue;
            }
            includeOnce(*name, file, lineNumber, depth);
            out_.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
        }
    }

    ResolvedShader take() { return std::move(out_); }
    ResolvedShader& result() { return out_; }

private:
    void includeOnce(const std::string& name, const std::string& includer, int lineNumber, int depth) {
        const std::string sibling = folderOf(includer) + name;
        for (const std::string& candidate : {sibling, name}) {
            if (included_.count(candidate)) return;
            if (const auto source = lookup_(candidate)) {
                append(candidate, *source, depth + 1);
                return;
            }
        }
        throw std::runtime_error(includer + ":" + std::to_string(lineNumber) + ": cannot find #include \"" + name + "\"");
    }

    const ShaderLookup& lookup_;
    ResolvedShader out_;
    std::set<std::string> included_;
};

} // namespace

ResolvedShader resolveIncludes(std::string_view mainFile, std::string_view version, std::string_view prelude,
                               const ShaderLookup& lookup) {
    const auto mainSource = lookup(mainFile);
    if (!mainSource) throw std::runtime_error(std::string(mainFile) + ": no such shader");
    Resolver resolver(lookup);
    ResolvedShader& out = resolver.result();
    out.text = std::string(version) + "\n";
    out.files.push_back("<prelude>");
    out.text += "#line 1 0\n";
    out.text.append(prelude);
    if (!out.text.empty() && out.text.back() != '\n') out.text += "\n";
    resolver.append(std::string(mainFile), *mainSource, 0);
    return resolver.take();
}

std::string mapLogToFiles(std::string_view log, const std::vector<std::string>& files) {
    static const std::regex location(R"((^|\n)(\d+)(?::(\d+)\(\d+\):|\((\d+)\) ?:))");
    std::string out;
    std::string text(log);
    auto tail = text.cbegin();
    for (std::sregex_iterator it(text.cbegin(), text.cend(), location), end; it != end; ++it) {
        const auto& m = *it;
        out.append(tail, m[0].first);
        const auto index = std::stoul(m[2].str());
        const std::string line = m[3].matched ? m[3].str() : m[4].str();
        const std::string file = index < files.size() ? files[index] : m[2].str();
        out += m[1].str() + file + ":" + line + ":";
        tail = m[0].second;
    }
    out.append(tail, text.cend());
    return out;
}

} // namespace glint::gl
