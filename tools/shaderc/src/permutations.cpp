#include "shaderc.h"

#include <algorithm>
#include <cctype>
#include <limits>

namespace ffxdof::shaderc {
namespace {

bool isIdentifier(const std::string& name) {
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
    return std::all_of(name.begin(), name.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

uint32_t parseAxisValue(const std::string& axisText, const std::string& value) {
    if (value.empty() || !std::all_of(value.begin(), value.end(), [](char c) { return std::isdigit(c) != 0; })) {
        throw Error("axis '" + axisText + "': value '" + value + "' is not a non-negative integer");
    }
    if (value.size() > 10 || std::stoull(value) > std::numeric_limits<uint32_t>::max()) {
        throw Error("axis '" + axisText + "': value '" + value + "' does not fit in 32 bits");
    }
    return static_cast<uint32_t>(std::stoul(value));
}

}  // namespace

const char* languageName(Language language) { return language == Language::Glsl ? "glsl" : "hlsl"; }

const char* tableLanguage(const CompileOptions& options) {
    return options.dxc.empty() ? languageName(options.language) : "dxil";
}

Language parseLanguage(const std::string& text) {
    if (text == "glsl") return Language::Glsl;
    if (text == "hlsl") return Language::Hlsl;
    throw Error("unknown language '" + text + "' (expected glsl or hlsl)");
}

Define parseDefine(const std::string& text) {
    const size_t equals = text.find('=');
    Define define{text.substr(0, equals), equals == std::string::npos ? "1" : text.substr(equals + 1)};
    if (!isIdentifier(define.name)) {
        throw Error("define '" + text + "': '" + define.name + "' is not a macro name (expected NAME=VALUE)");
    }
    if (define.value.find('\n') != std::string::npos) {
        throw Error("define '" + define.name + "': the value spans several lines");
    }
    return define;
}

Axis parseAxis(const std::string& text) {
    const size_t equals = text.find('=');
    const std::string syntax = " (expected NAME={v1,v2,...})";
    if (equals == std::string::npos) {
        throw Error("axis '" + text + "' has no value list" + syntax + "; use --define for a plain define");
    }
    Axis axis;
    axis.macro = text.substr(0, equals);
    if (!isIdentifier(axis.macro))
        throw Error("axis '" + text + "': '" + axis.macro + "' is not a macro name" + syntax);
    const std::string list = text.substr(equals + 1);
    if (list.size() < 2 || list.front() != '{' || list.back() != '}') {
        throw Error("axis '" + text + "': the values must be in braces" + syntax +
                    "; quote the option so the shell does not expand the braces, or use --define for a plain define");
    }
    const std::string inner = list.substr(1, list.size() - 2);
    if (inner.find_first_not_of(" ") == std::string::npos) throw Error("axis '" + axis.macro + "' has no values");
    size_t start = 0;
    while (start <= inner.size()) {
        const size_t comma = std::min(inner.find(',', start), inner.size());
        std::string value = inner.substr(start, comma - start);
        value.erase(std::remove(value.begin(), value.end(), ' '), value.end());
        const uint32_t parsed = parseAxisValue(text, value);
        if (std::find(axis.values.begin(), axis.values.end(), parsed) != axis.values.end()) {
            throw Error("axis '" + axis.macro + "' lists the value " + value + " twice");
        }
        axis.values.push_back(parsed);
        start = comma + 1;
    }
    return axis;
}

uint32_t permutationCount(const std::vector<Axis>& axes) {
    // permutationToBlob is uint16_t; a pass with more permutations than that is a design error.
    constexpr uint64_t kLimit = 65535;
    uint64_t count = 1;
    for (const Axis& axis : axes) {
        count *= axis.values.size();
        if (count > kLimit) throw Error("more than " + std::to_string(kLimit) + " permutations: reduce the axes");
    }
    return static_cast<uint32_t>(count);
}

std::vector<Define> permutationDefines(const std::vector<Axis>& axes, uint32_t index) {
    std::vector<Define> defines(axes.size());
    for (size_t a = axes.size(); a-- > 0;) {
        const Axis& axis = axes[a];
        defines[a] = {axis.macro, std::to_string(axis.values[index % axis.values.size()])};
        index /= static_cast<uint32_t>(axis.values.size());
    }
    return defines;
}

}  // namespace ffxdof::shaderc
