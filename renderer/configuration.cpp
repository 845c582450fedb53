#include "renderer/configuration.h"

#include <array>
#include <cctype>

namespace glint::renderer {
namespace {

constexpr std::array<Configuration, 6> allConfigurations{Configuration::Baseline, Configuration::Realistic,
                                                         Configuration::Full,     Configuration::Heavy,
                                                         Configuration::Accumulate, Configuration::Reference};

bool equalIgnoringCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
    return true;
}

} // namespace

ConfigurationTraits traitsOf(Configuration configuration) {
    switch (configuration) {
    case Configuration::Baseline: return {1, false, true, false, false, false}; // ambient term for the missing bounces
    case Configuration::Realistic: return {1, true, false, true, false, false};
    case Configuration::Full: return {1, true, false, true, true, false};
    case Configuration::Heavy: return {4, true, false, true, true, false};
    case Configuration::Accumulate:
    case Configuration::Reference: return {1, true, false, false, false, true};
    }
    return {};
}

std::string_view configurationName(Configuration configuration) {
    switch (configuration) {
    case Configuration::Baseline: return "baseline";
    case Configuration::Realistic: return "realistic";
    case Configuration::Full: return "full";
    case Configuration::Heavy: return "heavy";
    case Configuration::Accumulate: return "accumulate";
    case Configuration::Reference: return "reference";
    }
    return "accumulate";
}

std::optional<Configuration> parseConfiguration(std::string_view name) {
    for (const Configuration c : allConfigurations)
        if (equalIgnoringCase(name, configurationName(c))) return c;
    return std::nullopt;
}

std::string configurationNames() {
    std::string names;
    for (const Configuration c : allConfigurations) names += (names.empty() ? "" : ", ") + std::string(configurationName(c));
    return names;
}

} // namespace glint::renderer
