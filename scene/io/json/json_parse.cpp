#include "json_parse.h"

#include "scene/core/diagnostics.h"

#include <vector>

namespace glint {

namespace {

using nlohmann::json;

// Where the parser is: one entry per open object or array. The parser's callback reports each
// event in order, so the path of the value being read when an error is thrown is this stack.
class JsonPathTracker {
public:
    JsonPathTracker(const std::string& file, int maxDepth) : file_(file), maxDepth_(maxDepth) {}

    bool onEvent(json::parse_event_t event, const json& parsed)
    {
        if (int(open_.size()) > maxDepth_)
            throw FileError(file_, "json-too-deep", "the JSON nests deeper than " + std::to_string(maxDepth_) + " levels");
        switch (event) {
        case json::parse_event_t::object_start: open_.push_back({false, {}, 0}); break;
        case json::parse_event_t::array_start: open_.push_back({true, {}, 0}); break;
        case json::parse_event_t::key:
            if (!open_.empty() && parsed.is_string()) open_.back().key = parsed.get<std::string>();
            break;
        case json::parse_event_t::object_end:
        case json::parse_event_t::array_end:
            if (!open_.empty()) open_.pop_back();
            countElement();
            break;
        case json::parse_event_t::value: countElement(); break;
        }
        return true;
    }

    // `nodes[0].translation[0]`; "the top level" when nothing is open.
    std::string path() const
    {
        std::string out;
        for (const Level& level : open_) {
            if (level.array)
                out += "[" + std::to_string(level.count) + "]";
            else
                out += (out.empty() ? "" : ".") + level.key;
        }
        return out.empty() ? std::string("the top level") : out;
    }

private:
    struct Level {
        bool array;
        std::string key;
        std::size_t count; // elements of an array already read
    };

    void countElement()
    {
        if (!open_.empty() && open_.back().array) ++open_.back().count;
    }

    const std::string& file_;
    int maxDepth_;
    std::vector<Level> open_;
};

// The parser's message without its "[json.exception.<kind>.<id>] " prefix.
std::string plainMessage(const json::exception& e)
{
    std::string what = e.what();
    if (what.rfind("[json.exception.", 0) == 0) {
        const auto end = what.find("] ");
        if (end != std::string::npos) what.erase(0, end + 2);
    }
    return what;
}

// The number text in "number overflow parsing '1e400'".
std::string overflowingNumber(const std::string& message)
{
    const auto open = message.find('\'');
    const auto close = message.rfind('\'');
    return open != std::string::npos && close > open ? message.substr(open + 1, close - open - 1) : std::string("a number");
}

} // namespace

json parseJsonText(std::string_view text, const std::string& file, int maxDepth)
{
    JsonPathTracker tracker(file, maxDepth);
    try {
        return json::parse(text.begin(), text.end(),
                           [&tracker](int, json::parse_event_t event, json& parsed) { return tracker.onEvent(event, parsed); });
    } catch (const json::out_of_range& e) {
        // 406: a grammatically valid number beyond the range of a double.
        if (e.id != 406) throw FileError(file, "invalid-json", "not valid JSON: " + plainMessage(e));
        throw FileError(file, "non-finite-value",
                        tracker.path() + " is " + overflowingNumber(plainMessage(e)) + ", beyond the range of a number");
    } catch (const json::exception& e) {
        throw FileError(file, "invalid-json", "not valid JSON: " + plainMessage(e));
    }
}

} // namespace glint
