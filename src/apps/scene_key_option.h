#pragma once
// Command-line numbers that stand for a scene key (--spp for render.spp) are checked against the
// parameter table, so the command line refuses what the scene file refuses (NaN, infinity,
// negative or out-of-range values) with the same words.
#include "scene/parameters.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raylab {

// A CLI11 validator: the option's text must be one decimal number that `dottedKey` accepts.
inline CLI::Validator sceneKeyRange(std::string_view dottedKey) {
    const ParamSpec* spec = findParameter(dottedKey);
    if (!spec) throw std::logic_error("sceneKeyRange: no scene key " + std::string(dottedKey));
    return CLI::Validator(
        [spec](std::string& text) -> std::string {
            double value = 0.0;
            const char* begin = text.data() + (text.size() > 1 && text[0] == '+' ? 1 : 0);
            const auto [end, ec] = std::from_chars(begin, text.data() + text.size(), value);
            if (ec != std::errc() || end != text.data() + text.size()) return "expected a number, got '" + text + "'";
            if (auto problem = checkScalar(*spec, value)) return "as " + std::string(spec->key) + ", " + *problem;
            return "";
        },
        describeRange(*spec), std::string(dottedKey));
}

} // namespace raylab
