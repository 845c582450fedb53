#pragma once
// Errors and warnings that name the file and the problem (docs/CLI.md: "glint: FILE: what is wrong").
#include <stdexcept>
#include <string>
#include <vector>

namespace glint {

struct Warning {
    std::string file;
    std::string code;    // stable, machine-readable: "missing-texture", "skin-dropped", ...
    std::string message; // for people
    friend bool operator==(const Warning&, const Warning&) = default;
};

using Warnings = std::vector<Warning>;

// Thrown when a file cannot be read or written at all. what() is "FILE: message".
class FileError : public std::runtime_error {
public:
    FileError(std::string file, std::string code, const std::string& message)
        : std::runtime_error(file + ": " + message), file_(std::move(file)), code_(std::move(code)), message_(message) {}
    const std::string& file() const { return file_; }
    const std::string& code() const { return code_; }
    const std::string& message() const { return message_; }

private:
    std::string file_;
    std::string code_;
    std::string message_;
};

} // namespace glint
